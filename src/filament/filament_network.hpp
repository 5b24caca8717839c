// The cytoskeleton's state: filaments, the linkers and motors bound between them, and
// Arp2/3 branches, with the edits chemistry makes to them (grow, shrink, bind, unbind,
// walk, branch) and the flattened layout the energy terms read.
//
// Binding sites are fixed points of a filament's monomer lattice, every `spacing`
// monomers: site j sits at lattice coordinate (j + 1/2) * spacing and exists while the
// filament covers it. Each protein kind (linker type, motor type, brancher type) has its
// own sites; a site holds at most one protein of its kind.
#pragma once

#include <array>
#include <cstdint>
#include <set>
#include <vector>

#include "filament/filament.hpp"
#include "filament/filament_layout.hpp"
#include "filament/filament_params.hpp"
#include "mech/body.hpp"

namespace cortex {

// Which family of proteins a site lattice belongs to.
enum class BinderKind : std::uint8_t { kLinker, kMotor, kBrancher };

// A bound linker or motor: two ends on sites of two different filaments.
struct Binding {
  Index type = 0;                      // LinkerType / MotorType index
  std::array<Index, 2> filament{0, 0};
  std::array<std::int64_t, 2> site{0, 0};
  double rest_length = 0.0;            // nm: the distance at binding
  double tension = 0.0;                // pN, k (l - l0) at the last minimization; 0 until then
  Index compartment = 0;               // where its reactions fire: fixed at binding and at each
                                       // minimization (chemistry's bookkeeping, not state)
  int heads = 0;                       // motors: heads of this minifilament (0: not modelled)
};

// Events carried out since the start of the run (void events not counted; proteins
// released by a shrinking end are not unbinding events).
struct FilamentEvents {
  std::int64_t linker_bindings = 0, linker_unbindings = 0;
  std::int64_t motor_bindings = 0, motor_unbindings = 0, motor_steps = 0;
};

struct Branch {
  Index type = 0;          // BrancherType index
  Index mother = 0, daughter = 0;
  std::int64_t site = 0;   // brancher site on the mother
  Index compartment = 0;   // as Binding::compartment
};

// A protein set free when an end shrinks past it: one copy of `species` goes back to the
// compartment holding `where`.
struct Release {
  Index species;
  Vec3 where;
};

// The whole cytoskeleton; a Body whose points are all filaments' beads, filament after
// filament (minus end first).
class FilamentNetwork final : public Body {
 public:
  explicit FilamentNetwork(FilamentConfig config);

  // Body.
  const std::string& name() const override;
  Index numPoints() const override { return numBeads(); }
  void gather(double* x) const override;
  void scatter(const double* x) override;
  void frozen(char* mask) const override;  // anchored minus ends
  // Rebuilds the layout with the beads starting at `offset`.
  void setOffset(Index offset) override;
  // The layout's lists do not depend on where the beads start: only the offset changes.
  void moveOffset(Index offset) override;

  const FilamentConfig& config() const { return config_; }
  const FilamentType& type(Index t) const { return config_.types[t]; }
  const std::vector<Filament>& filaments() const { return filaments_; }
  std::vector<Filament>& filaments() { return filaments_; }
  const std::vector<Binding>& linkers() const { return linkers_; }
  const std::vector<Binding>& motors() const { return motors_; }
  const std::vector<Branch>& branches() const { return branches_; }
  std::vector<Branch>& branches() { return branches_; }
  std::vector<Binding>& bound(BinderKind kind) { return kind == BinderKind::kMotor ? motors_ : linkers_; }
  const std::vector<Binding>& bound(BinderKind kind) const { return kind == BinderKind::kMotor ? motors_ : linkers_; }

  // Filaments are never removed: an index is an identity for the whole run.
  Index addFilament(Filament f);

  // --- sites -----------------------------------------------------------------------
  int spacing(BinderKind kind, Index type) const;
  double siteCoordinate(BinderKind kind, Index type, std::int64_t site) const {
    return (static_cast<double>(site) + 0.5) * spacing(kind, type);
  }
  bool siteExists(BinderKind kind, Index type, Index filament, std::int64_t site) const {
    return filaments_[filament].covers(siteCoordinate(kind, type, site));
  }
  bool occupied(BinderKind kind, Index type, Index filament, std::int64_t site) const {
    return occupied_.count(key(kind, type, filament, site)) != 0;
  }
  // Sites of `kind`/`type` on cylinder c of filament f: [first, last] (empty if first > last).
  std::pair<std::int64_t, std::int64_t> sitesOnCylinder(BinderKind kind, Index type, Index f, Index c) const;
  Vec3 sitePosition(BinderKind kind, Index type, Index filament, std::int64_t site) const {
    return filaments_[filament].pointAt(siteCoordinate(kind, type, site));
  }

  // --- chemistry's edits -------------------------------------------------------------
  // Smallest filament: a dimer, or the Arp2/3 complex alone for a capped daughter.
  std::int64_t minimumMonomers(const Filament& f) const { return f.minus_capped ? 1 : 2; }
  // Adds one monomer at an end: the end bead moves out by one monomer size along its
  // cylinder, or, when that cylinder is full, a new bead one monomer size beyond it.
  void grow(Index f, bool plus_end);
  // Removes one monomer (false, nothing done, at the minimum size). Proteins bound to
  // the lost monomer's site range are released into `released`.
  bool shrink(Index f, bool plus_end, std::vector<Release>& released);
  void bind(BinderKind kind, const Binding& b);  // kLinker or kMotor; sites must be free
  void unbind(BinderKind kind, std::size_t index);
  // Moves end `end` of motor `index` one site towards the plus end; false if that site
  // does not exist or is occupied.
  bool walk(std::size_t index, int end);
  // A daughter of one monomer, capped by the Arp2/3 complex, on `site` of `mother`, leaving at the
  // brancher's angle in direction `daughter_direction` (unit). Returns the daughter.
  Index branch(Index type, Index mother, std::int64_t site, const Vec3& daughter_direction);
  void unbranch(std::size_t index);

  // --- mechanics ---------------------------------------------------------------------
  Index numBeads() const;
  double totalLength() const;  // nm, over every filament
  // The layout, rebuilt by setOffset after chemistry changed the network; bead b of the
  // layout is filament f's bead i in filament order.
  const FilamentLayout& layout() const { return layout_; }
  Index firstBead(Index f) const { return bead_start_[f]; }  // valid after setOffset

  FilamentEvents& events() { return events_; }
  const FilamentEvents& events() const { return events_; }

  // Restoring from a checkpoint.
  void restore(std::vector<Filament> filaments, std::vector<Binding> linkers, std::vector<Binding> motors,
               std::vector<Branch> branches);

 private:
  using Key = std::array<std::int64_t, 3>;
  static Key key(BinderKind kind, Index type, Index filament, std::int64_t site) {
    return {static_cast<std::int64_t>(kind) << 32 | type, filament, site};
  }
  CylinderPoint attachment(BinderKind kind, Index type, Index filament, std::int64_t site) const;
  void releaseBeyond(Index f, std::vector<Release>& released);

  FilamentConfig config_;
  std::vector<Filament> filaments_;
  std::vector<Binding> linkers_, motors_;
  std::vector<Branch> branches_;
  FilamentEvents events_;
  std::set<Key> occupied_;
  std::vector<Index> bead_start_;
  FilamentLayout layout_;
};

}  // namespace cortex
