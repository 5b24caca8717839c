// Excluded volume between a membrane and filament beads (thesis eq. 2.13, appendix A.5):
//   E = k_excl Σ_beads Σ_triangles S(d_t) ∫_t dS / d⁴,
// d the distance from the bead to the points of the triangle, the integral in closed form
// (triangle_inverse_fourth.hpp) with exact gradients on the bead and the three vertices.
// S fades a triangle out smoothly as the bead's distance d_t to its nearest point goes
// from cutoff/2 to cutoff (S = 1 − 10x³ + 15x⁴ − 6x⁵): a hard cut-off would make the
// energy jump by k A_t/d⁴ whenever a triangle of area A_t crosses it, which stalls line
// searches. Over a flat membrane what the fade leaves out depends on the distance alone,
// so for a bead closer than cutoff/2 it is a constant energy ≤ k π/(cutoff/2)² (3.1 pN·nm
// with the defaults) and no force; farther out the push fades to zero at the cut-off
// (the full membrane's is ≤ 2π k/(cutoff/2)³ = 0.63 pN there); docs/coupling.md. A bead
// on a triangle has infinite energy: minimizers back off.
//
// Pairs come from a Verlet list of (triangle, bead) within cutoff + skin, found with a
// cell list over triangle centroids. A triangle's points move by at most the largest move
// of its vertices, so the list stays complete until the largest vertex move plus the
// largest bead move exceed the skin; it is rebuilt then, when the membrane is remeshed or
// the network's layout changes. Pairs are kept in (triangle, bead) order and filtered by
// the exact distance at every evaluation, so the energy does not depend on when the list
// was built.
//
// The term acts on the membrane (its owner, under whose name summary.json lists it) and
// on the filament network. In a membrane's own relaxation (Evaluation::alone) the beads
// stay where the network holds them, and in the filaments' the vertices where the mesh
// holds them; in a relaxation of everything both move. A trial point that has carried a
// bead through a triangle it lies over, relative to where the bodies hold them, has
// infinite energy (crossesSinceHeld): the far side's energy is finite and a long step
// could otherwise land there.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "filament/filament_network.hpp"
#include "interact/triangle_cells.hpp"
#include "interact/triangle_inverse_fourth.hpp"
#include "mech/energy_term.hpp"
#include "membrane/membrane.hpp"

namespace cortex {

enum class ExclusionBeads { kAll, kEnds, kPlusEnds };

struct MembraneBeadExclusionParams {
  double stiffness = 100.0;  // k_excl, pN·nm³
  double cutoff = 20.0;      // nm
  ExclusionBeads beads = ExclusionBeads::kAll;
};

class MembraneBeadExclusion final : public EnergyTerm {
 public:
  MembraneBeadExclusion(const Membrane& membrane, const FilamentNetwork& network, MembraneBeadExclusionParams params);
  const std::string& name() const override;
  const std::string& owner() const override { return membrane_.name(); }
  bool actsOn(const std::string& body) const override {
    return body == membrane_.name() || body == network_.name();
  }
  bool isContact() const override { return true; }
  double evaluate(const Evaluation& e) override;

  const MembraneBeadExclusionParams& params() const { return params_; }
  // The force (pN) the membrane, where it is held, puts on a bead at p, with the cells of
  // its triangles as held (heldCells(): rebuild after the membrane moved). For the
  // ratchet between relaxations, when the membrane stands still.
  Vec3 forceAt(const Vec3& p, const TriangleCells& held) const;
  TriangleCells heldCells() const;
  const Membrane& membrane() const { return membrane_; }
  const FilamentNetwork& network() const { return network_; }
  // Diagnostics, for tests, benchmarks and the log.
  std::int64_t rebuilds() const { return rebuilds_; }
  std::size_t listedPairs() const { return pairs_.size(); }
  std::size_t activePairs() const { return active_pairs_; }  // within the cut-off at the last evaluation

 private:
  struct Pair {
    Index face, bead;  // bead: index into beads_ (the selected beads)
  };
  // One bead and one triangle: inactive beyond the cut-off; the energy (pN·nm, infinite
  // on the triangle) and, if asked (`gradient`), its gradient on the bead and, unless
  // kPoint, the three vertices (zero then).
  struct PairEnergy {
    bool active = false;
    double energy = 0.0;
    Vec3 d_point = Vec3::Zero();
    std::array<Vec3, 3> d_vertices{Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
  };
  PairEnergy pairEnergy(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c,
                        std::optional<InverseFourthGradient> gradient) const;
  // Positions of the vertices and selected beads at e (from e or from the bodies; what
  // was read from a body is kept while e.held stays the same).
  void gatherPositions(const Evaluation& e);
  bool listIsStale();
  // Whether a bead lies over a listed triangle on the other side than where the bodies
  // hold them (the last accepted positions): a step that carried a bead through the
  // membrane, or the membrane over a bead, which the energy, finite again on the far
  // side, would not see. Such a point gets infinite energy, so minimizers back off.
  bool crossesSinceHeld(const Evaluation& e);
  void rebuild();

  const Membrane& membrane_;
  const FilamentNetwork& network_;
  MembraneBeadExclusionParams params_;
  double skin_;
  std::vector<Index> beads_;  // selected beads, as indices into the network's bead layout
  std::vector<Vec3> vertex_x_, bead_x_;
  std::vector<double> held_beads_;  // the network's own positions at the last evaluation
  std::uint64_t held_ = 0;          // Evaluation::held of the last evaluation
  // The largest moves since the last build (nm), or negative when not known: a body held
  // through a relaxation moves nothing, and a filament relaxation beside a membrane of
  // thousands of vertices spent more on measuring their moves than on its beads' forces.
  double vertex_move_ = -1.0, bead_move_ = -1.0;
  std::vector<Pair> pairs_;
  // At the last build.
  bool built_ = false;
  std::uint64_t built_connectivity_ = 0, built_layout_ = 0;
  std::vector<Vec3> built_vertex_x_, built_bead_x_;
  TriangleCells cells_;  // of the triangles at built_vertex_x_
  std::int64_t rebuilds_ = 0;
  std::size_t active_pairs_ = 0;
};

}  // namespace cortex
