#include "io/summary.hpp"

#include <cmath>
#include <numeric>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "mesh/mesh_quality.hpp"

namespace cortex {

namespace {

nlohmann::json chemistrySummary(const System& system) {
  using nlohmann::json;
  const ChemistryEngine* chem = system.chemistry();
  if (!chem) return {{"events", 0}, {"species", json::object()}};
  const ChemistryModel& model = system.chemistryModel();
  json species = json::object();
  for (Index s = 0; s < static_cast<Index>(model.species.size()); ++s) {
    std::int64_t total = 0;
    // Over every subvolume: compartments, and the vertices of membranes with species.
    for (Index c = 0; c < chem->numSubvolumes(); ++c) total += chem->copies(c, s);
    species[model.species[s].name] = total;
  }
  json reactions = json::array();
  for (std::size_t r = 0; r < model.reactions.size(); ++r)
    reactions.push_back({{"equation", model.reactions[r].equation}, {"events", chem->reactionEvents()[r]}});
  return {{"events", chem->events()},
          {"diffusion_events", chem->diffusionEvents()},
          {"reactions", reactions},
          {"compartments", system.grid().count()},
          {"species", species},
          {"surface_edges_closed", {{"cotangent", system.closedSurfaceEdges()[0]},
                                    {"linear_drift", system.closedSurfaceEdges()[1]}}}};
}

// Bound proteins per type name (every configured type listed, 0 when none is bound).
template <class Types, class Items>
nlohmann::json countByType(const Types& types, const Items& items) {
  std::vector<std::int64_t> counts(types.size(), 0);
  for (const auto& item : items) ++counts.at(static_cast<std::size_t>(item.type));
  nlohmann::json json = nlohmann::json::object();
  for (std::size_t t = 0; t < types.size(); ++t) json[types[t].name] = counts[t];
  return json;
}

nlohmann::json filamentSummary(const System& system, const std::vector<TermEnergy>& energies) {
  using nlohmann::json;
  const FilamentNetwork* net = system.filaments();
  if (!net) return {{"count", 0}, {"total_length", 0.0}, {"energy", {{"total", 0.0}}}};
  json energy = {{"stretching", 0.0}, {"bending", 0.0}, {"excluded_volume", 0.0}, {"boundary", 0.0},
                 {"linkers", 0.0},    {"motors", 0.0},  {"branching", 0.0}};
  double total_energy = 0.0;
  for (const TermEnergy& e : energies)
    if (e.owner == "filaments") {
      energy[e.name] = e.energy;
      total_energy += e.energy;
    }
  energy["total"] = total_energy;
  std::int64_t monomers = 0;
  const auto& filaments = net->filaments();
  for (const Filament& f : filaments) monomers += f.monomers();
  const double total_length = net->totalLength();
  const FilamentChemistry* chem = system.filamentChemistry();
  const FilamentConfig& config = net->config();
  const auto count = static_cast<std::int64_t>(filaments.size());
  return {{"count", count},
          {"beads", net->numBeads()},
          {"total_length", total_length},
          {"mean_length", count > 0 ? total_length / static_cast<double>(count) : 0.0},
          {"monomers", monomers},
          {"max_end_load", chem ? chem->maxEndLoad() : 0.0},
          {"energy", energy},
          {"linkers", countByType(config.linkers, net->linkers())},
          {"motors", countByType(config.motors, net->motors())},
          {"branches", countByType(config.branchers, net->branches())},
          {"events",
           {{"linker_bindings", net->events().linker_bindings},
            {"linker_unbindings", net->events().linker_unbindings},
            {"motor_bindings", net->events().motor_bindings},
            {"motor_unbindings", net->events().motor_unbindings},
            {"motor_steps", net->events().motor_steps}}}};
}

}  // namespace

nlohmann::json summarize(System& system, const RunInfo& info) {
  using nlohmann::json;
  const std::vector<TermEnergy> energies = system.forceField().breakdown(system.coordinates());
  json membranes = json::array();
  for (const auto& m : system.membranes()) {
    json energy = {{"bending", 0.0}, {"area", 0.0}, {"tension", 0.0}, {"volume", 0.0}};
    double total = 0.0;
    for (const TermEnergy& e : energies)
      if (e.owner == m->name()) {
        energy[e.name] = e.energy;
        total += e.energy;
      }
    energy["total"] = total;
    const MeshGeometry g = m->currentGeometry();
    // Copies of each membrane species on it (the same totals as chemistry.species).
    json species = json::object();
    for (std::size_t j = 0; j < m->speciesNames().size(); ++j) {
      const std::vector<int>& copies = m->speciesCopies()[j];
      species[m->speciesNames()[j]] = std::accumulate(copies.begin(), copies.end(), std::int64_t{0});
    }
    json entry = {{"name", m->name()},
                  {"vertices", m->mesh().numVertices()},
                  {"triangles", m->mesh().numFaces()},
                  {"area", g.area},
                  {"energy", energy},
                  {"species", species}};
    const MeshQuality q = measureQuality(m->mesh());
    entry["quality"] = {{"min_angle_deg", q.min_angle_deg},
                        {"max_aspect_ratio", q.max_aspect_ratio},
                        {"min_dihedral_cos", q.min_dihedral_cos}};
    const RemeshStats& r = m->remeshTotals();
    entry["remesh"] = {{"enabled", m->remeshing().has_value()}, {"sweeps", r.sweeps},
                       {"splits", r.splits}, {"collapses", r.collapses}, {"flips", r.flips},
                       {"relocations", r.relocations}};
    if (m->isClosed()) {
      entry["volume"] = g.volume;
      entry["reduced_volume"] = g.volume / sphereVolumeOfArea(g.area);
    } else {
      entry["volume"] = nullptr;  // an open patch encloses no volume
    }
    // Multipliers of exact constraints; null where the area or volume is not held exactly.
    const auto orNull = [](double v) { return std::isnan(v) ? nlohmann::json(nullptr) : nlohmann::json(v); };
    entry["tension"] = orNull(m->equilibrium().tension);
    // The coat's mean coverage Σ n φ / Σ n (Membrane::coatCoverage): what the curvature
    // generation sees, and what the thinning check watches.
    entry["coat_coverage"] = orNull(m->coatCoverage());
    entry["pressure"] = orNull(m->equilibrium().pressure);
    membranes.push_back(entry);
  }
  const RunCounters& c = system.counters;
  const ForceField& ff = system.forceField();
  return {{"time", system.time()},
          {"wall_seconds", info.wall_seconds},
          {"seed", info.seed},
          {"threads", info.threads},
          {"membranes", membranes},
          {"filaments", filamentSummary(system, energies)},
          {"chemistry", chemistrySummary(system)},
          {"mechanics",
           {{"minimizations", c.minimizations},
            {"minimizer_iterations", c.minimizer_iterations},
            {"unconverged_minimizations", c.unconverged_minimizations},
            {"last_max_force", c.last_max_force},
            {"force_evaluations", ff.forceEvaluations()},
            {"energy_evaluations", ff.energyEvaluations()}}}};
}

void writeJsonAtomically(const std::filesystem::path& file, const nlohmann::json& json) {
  writeFileAtomically(file, json.dump(2) + "\n");
}

}  // namespace cortex
