// Proteins on membranes in a run (thesis chapter 3): the copies of each membrane's
// surface species live on its vertices (Membrane::speciesCopies, carried through
// remeshing and stored in checkpoints) and, during a chemistry window, in the engine's
// surface subvolumes, the dual cells of those vertices (sim/surface_graph.hpp).
//
// The hand-over is exact both ways: after every relaxation (the mesh moved and may have
// been remeshed) the dual cells are rebuilt and the membrane's copies become the
// engine's; after every chemistry window the engine's copies go back to the vertices.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "sim/feedback.hpp"
#include "sim/run_config.hpp"

namespace cortex {

// Spreads every [[membrane.species]]' initial copies over its membrane's vertices (those
// inside its `region`, if given), each copy on vertex j with probability proportional to
// the dual-cell area |C_j| (stream kSurfaceSpeciesPlacement). Throws InputError (naming
// `source`) for a region holding no vertex or a density giving more than 2e9 copies.
void placeSurfaceSpecies(const std::vector<MembraneConfig>& configs, std::vector<std::unique_ptr<Membrane>>& membranes,
                         std::uint64_t seed, const std::string& source);

class SurfaceSpeciesFeedback final : public Feedback {
 public:
  // `config_factors`: the rate factors of the config's reactions (numbered model-wide
  // from config_factors.range().begin), of which this writes those of unbinding
  // reactions on the vertices.
  // `thermal_energy` k_BT (pN nm).
  SurfaceSpeciesFeedback(const ChemistryConfig& config, const std::vector<MembraneConfig>& membrane_configs,
                         ChemistryEngine& engine, const std::vector<std::unique_ptr<Membrane>>& membranes,
                         RateFactors config_factors, double thermal_energy);
  // The membranes' dual cells and copies become the engine's surfaces, the species'
  // potentials at the vertices' new positions their drift (sim/surface_drift.hpp): the
  // external one plus, for curvature-sensing species, V_H at each vertex's mean
  // curvature and current copies (sim/curvature_sensing.hpp: V_H(n) for a copy arriving,
  // V_H(n − 1) for one leaving; held until the next update, i.e. for one chemistry
  // window), and
  // unbinding reactions fire at r e^{βV} (thesis eq. 3.14): a reaction whose reactants
  // include membrane species with a potential and whose products are all 3D species
  // gets the factor exp(Σ ν_s V_s(j)) on vertex j (V in k_BT, the leaving copy's energy;
  // ν_s its reactant count).
  void update(System& system) override;
  // The engine's surface copies go back to the membranes' vertices (after a window).
  void collect(System& system) const;
  // Edges left out at the last update, summed over the membranes: for every species,
  // because their cotangent sum was negative (DualCellGraph::clipped_edges); for one
  // species, because its linear drift closed them (DriftFactors::closed_edges, summed
  // over species).
  struct ClosedEdges {
    Index cotangent = 0, drift = 0;
  };
  const ClosedEdges& closedEdges() const { return closed_; }

 private:
  struct Surface {
    Index membrane;              // index in the System's membranes
    std::vector<Index> species;  // model indices, in the membrane's species order
    std::vector<SurfaceSpeciesConfig> configs;  // likewise
    // The first reaction joining its species with 3D species (`reaction.N.equation`), or
    // empty: with one, the membrane must stay within the compartment grid.
    std::string joined_to_3d;
  };
  // External potential (k_BT) per vertex of each species that has one, empty for the others.
  std::vector<std::vector<double>> potentials(const Surface& s, const Membrane& membrane) const;
  // Curvature sensing as the engine's on-site energy (ChemistryEngine::SurfaceInteraction):
  // at vertex v the arrival energy a_v(m) = V_H(m others)/k_BT for m = 0 up to the count
  // that covers the cell (φ = 1, past which V_H stays) or fills it (footprint).
  void setSensingRows(const SurfaceSpeciesConfig& c, const Membrane& membrane, const SubvolumeGraph& cells,
                      const std::vector<double>& curvature, double t,
                      ChemistryEngine::SurfaceInteraction& interaction) const;
  struct Unbinding {
    Index reaction;  // model index
    Index surface;
    std::vector<std::pair<Index, int>> reactants;  // (index in Surface::species, count) with a potential
  };
  // Throws RunError, naming the membrane, vertex and species' potential keys, when a factor
  // e^{βV} would overflow.
  void setUnbindingFactors(Index surface, const std::string& membrane_name,
                           const std::vector<std::vector<double>>& potentials, Index vertices, double t) const;

  CompartmentGrid grid_;
  ChemistryEngine& engine_;
  Index species_count_;
  std::vector<Surface> surfaces_;  // in ChemistryModel::surfaces order
  std::vector<Unbinding> unbinding_;
  RateFactors factors_;
  ClosedEdges closed_;
  double thermal_energy_;
};

}  // namespace cortex
