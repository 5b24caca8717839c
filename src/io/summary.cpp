#include "io/summary.hpp"

#include <fstream>

#include "core/error.hpp"
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
    for (Index c = 0; c < model.grid.count(); ++c) total += chem->copies(c, s);
    species[model.species[s].name] = total;
  }
  json reactions = json::array();
  for (std::size_t r = 0; r < model.reactions.size(); ++r)
    reactions.push_back({{"equation", model.reactions[r].equation}, {"events", chem->reactionEvents()[r]}});
  return {{"events", chem->events()},
          {"diffusion_events", chem->diffusionEvents()},
          {"reactions", reactions},
          {"compartments", model.grid.count()},
          {"species", species}};
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
    json entry = {{"name", m->name()},
                  {"vertices", m->mesh().numVertices()},
                  {"triangles", m->mesh().numFaces()},
                  {"area", g.area},
                  {"energy", energy},
                  {"species", json::object()}};
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
    membranes.push_back(entry);
  }
  const RunCounters& c = system.counters;
  const ForceField& ff = system.forceField();
  return {{"time", system.time()},
          {"wall_seconds", info.wall_seconds},
          {"seed", info.seed},
          {"threads", info.threads},
          {"membranes", membranes},
          {"filaments", {{"count", 0}, {"total_length", 0.0}, {"energy", {{"total", 0.0}}}}},
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
  const std::filesystem::path tmp = file.string() + ".tmp";
  {
    std::ofstream out(tmp);
    out << json.dump(2) << '\n';
    if (!out) throw RunError("cannot write " + tmp.string());
  }
  std::filesystem::rename(tmp, file);
}

}  // namespace cortex
