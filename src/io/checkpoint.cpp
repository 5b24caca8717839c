#include "io/checkpoint.hpp"

#include <fmt/format.h>

#include "core/error.hpp"
#include "io/filament_checkpoint.hpp"
#include "io/hdf5_file.hpp"

namespace cortex {
namespace {

constexpr const char* kFormat = "cortex checkpoint 1";

std::vector<double> flatten(const std::vector<Vec3>& p) {
  std::vector<double> x;
  x.reserve(3 * p.size());
  for (const Vec3& v : p) x.insert(x.end(), {v.x(), v.y(), v.z()});
  return x;
}

void writeChemistry(h5::File& f, const ChemistryEngine& chem, const ChemistryModel& model) {
  const auto species = static_cast<Index>(model.species.size());
  std::vector<std::int32_t> copies;
  copies.reserve(static_cast<std::size_t>(model.grid.count()) * species);
  for (Index c = 0; c < model.grid.count(); ++c)
    for (Index s = 0; s < species; ++s) copies.push_back(chem.copies(c, s));
  f.write("/chemistry/copies", copies, {static_cast<hsize_t>(model.grid.count()), static_cast<hsize_t>(species)});
  f.write("/chemistry/reaction_events", chem.reactionEvents());
  f.setAttribute("/chemistry", "random_counter", static_cast<std::int64_t>(chem.random().counter()));
  f.setAttribute("/chemistry", "random_used", static_cast<std::int64_t>(chem.random().usedInBlock()));
  f.setAttribute("/chemistry", "time", chem.time());
  f.setAttribute("/chemistry", "events", chem.events());
  f.setAttribute("/chemistry", "diffusion_events", chem.diffusionEvents());
}

ChemistryState readChemistry(const h5::File& f) {
  ChemistryState s;
  const std::vector<std::int32_t> copies = f.readInt32("/chemistry/copies");
  s.copies.assign(copies.begin(), copies.end());
  s.reaction_events = f.readInt64("/chemistry/reaction_events");
  s.random_counter = static_cast<std::uint64_t>(f.attributeInt64("/chemistry", "random_counter"));
  s.random_used = static_cast<int>(f.attributeInt64("/chemistry", "random_used"));
  s.time = f.attributeDouble("/chemistry", "time");
  s.events = f.attributeInt64("/chemistry", "events");
  s.diffusion_events = f.attributeInt64("/chemistry", "diffusion_events");
  return s;
}

}  // namespace

void writeCheckpoint(const std::filesystem::path& file, const CheckpointHeader& header, const System& system) {
  const std::filesystem::path tmp = file.string() + ".tmp";
  {
    h5::File f = h5::File::create(tmp);
    f.createGroups("/run");
    f.setAttribute("/run", "format", std::string(kFormat));
    f.setAttribute("/run", "config", header.config_toml);
    f.setAttribute("/run", "config_source", header.config_source);
    f.setAttribute("/run", "base_dir", header.base_dir);
    f.setAttribute("/run", "next_snapshot", header.next_snapshot);
    f.setAttribute("/run", "time", system.time());
    f.setAttribute("/run", "step", system.step);
    const RunCounters& c = system.counters;
    f.setAttribute("/run", "minimizations", c.minimizations);
    f.setAttribute("/run", "minimizer_iterations", c.minimizer_iterations);
    f.setAttribute("/run", "unconverged_minimizations", c.unconverged_minimizations);
    f.setAttribute("/run", "last_max_force", c.last_max_force);
    f.setAttribute("/run", "mechanics_seconds", c.mechanics_seconds);
    f.setAttribute("/run", "remesh_seconds", c.remesh_seconds);
    f.setAttribute("/run", "chemistry_seconds", c.chemistry_seconds);
    f.setAttribute("/run", "force_evaluations", system.forceField().forceEvaluations());
    f.setAttribute("/run", "energy_evaluations", system.forceField().energyEvaluations());
    for (const auto& m : system.membranes()) {
      const std::string g = "/membranes/" + m->name();
      const auto n = static_cast<hsize_t>(m->mesh().numVertices());
      f.write(g + "/vertices", flatten(m->mesh().positions()), {n, 3});
      std::vector<std::int32_t> tris;
      for (const Tri& t : m->topology().triangles) tris.insert(tris.end(), t.begin(), t.end());
      f.write(g + "/triangles", tris, {tris.size() / 3, 3});
      std::vector<std::int8_t> fixed(m->fixedVertices().begin(), m->fixedVertices().end());
      f.write(g + "/fixed", fixed);
      f.write(g + "/vertex_area0", m->material().vertex_area0);
      f.setAttribute(g, "initial_area", m->material().initial_area);
      f.setAttribute(g, "initial_volume", m->material().initial_volume);
      if (const auto& rs = m->remeshing()) {
        const SizingParameters& z = rs->sizing;
        f.write(g + "/remesh_sizing", std::vector<double>{z.flat_size, z.min_size, z.max_size, z.tolerance});
      }
      const RemeshStats& r = m->remeshTotals();
      f.write(g + "/remesh_totals", std::vector<std::int64_t>{r.sweeps, r.splits, r.collapses, r.flips, r.relocations});
    }
    if (const ChemistryEngine* chem = system.chemistry()) writeChemistry(f, *chem, system.chemistryModel());
    if (const FilamentNetwork* net = system.filaments()) writeFilamentState(f, *net);
    f.flush();
  }
  std::filesystem::rename(tmp, file);
}

Checkpoint readCheckpoint(const std::filesystem::path& file) {
  if (!std::filesystem::exists(file))
    throw InputError(fmt::format("{}: no checkpoint to resume from", file.string()));
  h5::File f = h5::File::openReadOnly(file);
  if (!f.exists("/run") || f.attributeString("/run", "format") != kFormat)
    throw InputError(fmt::format("{}: not a cortex checkpoint (or from an incompatible version)", file.string()));
  Checkpoint cp;
  cp.header.config_toml = f.attributeString("/run", "config");
  cp.header.config_source = f.attributeString("/run", "config_source");
  cp.header.base_dir = f.attributeString("/run", "base_dir");
  cp.header.next_snapshot = f.attributeInt64("/run", "next_snapshot");
  cp.time = f.attributeDouble("/run", "time");
  cp.step = f.attributeInt64("/run", "step");
  cp.counters.minimizations = f.attributeInt64("/run", "minimizations");
  cp.counters.minimizer_iterations = f.attributeInt64("/run", "minimizer_iterations");
  cp.counters.unconverged_minimizations = f.attributeInt64("/run", "unconverged_minimizations");
  cp.counters.last_max_force = f.attributeDouble("/run", "last_max_force");
  cp.counters.mechanics_seconds = f.attributeDouble("/run", "mechanics_seconds");
  cp.counters.remesh_seconds = f.attributeDouble("/run", "remesh_seconds");
  cp.counters.chemistry_seconds = f.attributeDouble("/run", "chemistry_seconds");
  cp.force_evaluations = f.attributeInt64("/run", "force_evaluations");
  cp.energy_evaluations = f.attributeInt64("/run", "energy_evaluations");
  for (const std::string& name : f.exists("/membranes") ? f.children("/membranes") : std::vector<std::string>{}) {
    const std::string g = "/membranes/" + name;
    MembraneState s;
    const std::vector<double> x = f.readDoubles(g + "/vertices");
    for (std::size_t i = 0; i + 2 < x.size(); i += 3) s.mesh.positions.emplace_back(x[i], x[i + 1], x[i + 2]);
    const std::vector<std::int32_t> t = f.readInt32(g + "/triangles");
    for (std::size_t i = 0; i + 2 < t.size(); i += 3) s.mesh.triangles.push_back({t[i], t[i + 1], t[i + 2]});
    const std::vector<std::int8_t> fixed = f.readInt8(g + "/fixed");
    s.fixed.assign(fixed.begin(), fixed.end());
    s.material.vertex_area0 = f.readDoubles(g + "/vertex_area0");
    s.material.initial_area = f.attributeDouble(g, "initial_area");
    s.material.initial_volume = f.attributeDouble(g, "initial_volume");
    if (f.exists(g + "/remesh_sizing")) {
      const std::vector<double> z = f.readDoubles(g + "/remesh_sizing");
      if (z.size() != 4) throw InputError(fmt::format("{}: {}/remesh_sizing is malformed", file.string(), g));
      RemeshSettings rs;
      rs.sizing.flat_size = z[0], rs.sizing.min_size = z[1], rs.sizing.max_size = z[2], rs.sizing.tolerance = z[3];
      s.remeshing = rs;
    }
    if (s.fixed.size() != s.mesh.positions.size() || s.material.vertex_area0.size() != s.mesh.positions.size())
      throw InputError(fmt::format("{}: {}: per-vertex arrays do not match the vertex count", file.string(), g));
    const std::vector<std::int64_t> r = f.readInt64(g + "/remesh_totals");
    if (r.size() != 5) throw InputError(fmt::format("{}: {}/remesh_totals is malformed", file.string(), g));
    s.remesh_totals = {r[1], r[2], r[3],
                       r[4], r[0]};
    cp.membranes.emplace(name, std::move(s));
  }
  if (f.exists("/chemistry")) cp.chemistry = readChemistry(f);
  if (f.exists("/filaments")) cp.filaments = readFilamentState(f, file.string());
  return cp;
}

}  // namespace cortex
