#include "io/checkpoint.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "core/error.hpp"
#include "core/hash.hpp"
#include "io/atomic_file.hpp"
#include "io/filament_checkpoint.hpp"
#include "io/hdf5_file.hpp"
#include "io/observables.hpp"

namespace cortex {
namespace {

constexpr const char* kFormat = "cortex checkpoint 2";
// The user block, 512 bytes before the HDF5 image (HDF5 ignores them): "<format>\nfnv1a64
// <16 hex digits of the hash of every later byte>\n", zero-padded.
constexpr std::size_t kUserBlock = 512;

std::string stampLine(std::string_view bytes) {
  return fmt::format("{}\nfnv1a64 {:016x}\n", kFormat, fnv1a64(bytes.substr(kUserBlock)));
}

// The file's bytes, checked against their stamp.
void verifyStamp(const std::filesystem::path& file) {
  const std::string bytes = readWholeFile(file, std::size_t{1} << 40);
  if (bytes.size() <= kUserBlock || bytes.compare(0, std::string(kFormat).size() + 1, std::string(kFormat) + "\n") != 0)
    throw InputError(fmt::format("{}: not a cortex checkpoint of format \"{}\" (another program's file, or an "
                                 "older cortex's)",
                                 file.string(), kFormat));
  const std::string stamp = stampLine(bytes);
  if (bytes.compare(0, stamp.size(), stamp) != 0)
    throw InputError(fmt::format("{}: damaged (its content no longer matches its checksum); it cannot be resumed",
                                 file.string()));
}

// The state structs list their scalar fields once (fields()); these visitors store them
// as attributes of one group and read them back, so the two directions cannot drift.
struct AttributeWriter {
  h5::File& file;
  std::string group;
  void operator()(const char* name, double value) const { file.setAttribute(group, name, value); }
  template <class T>
    requires std::is_integral_v<T>
  void operator()(const char* name, T value) const {
    file.setAttribute(group, name, static_cast<std::int64_t>(value));
  }
};

struct AttributeReader {
  const h5::File& file;
  std::string group;
  void operator()(const char* name, double& value) const { value = file.attributeDouble(group, name); }
  template <class T>
    requires std::is_integral_v<T>
  void operator()(const char* name, T& value) const {
    value = static_cast<T>(file.attributeInt64(group, name));
  }
};

// Body names joined by '/', which no name may contain.
std::string joinNames(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : "/") + n;
  return out;
}

std::vector<std::string> splitNames(const std::string& joined) {
  std::vector<std::string> out;
  if (joined.empty()) return out;
  std::size_t start = 0;
  for (std::size_t slash; (slash = joined.find('/', start)) != std::string::npos; start = slash + 1)
    out.push_back(joined.substr(start, slash - start));
  out.push_back(joined.substr(start));
  return out;
}

void writeMembrane(h5::File& f, const std::string& g, const MembraneState& s) {
  const auto n = static_cast<hsize_t>(s.mesh.positions.size());
  f.write(g + "/vertices", flatCoordinates(s.mesh.positions), {n, 3});
  std::vector<std::int32_t> tris;
  for (const Tri& t : s.mesh.triangles) tris.insert(tris.end(), t.begin(), t.end());
  f.write(g + "/triangles", tris, {tris.size() / 3, 3});
  f.write(g + "/fixed", std::vector<std::int8_t>(s.fixed.begin(), s.fixed.end()));
  f.write(g + "/vertex_area0", s.material.vertex_area0);
  if (!s.metric.positions.empty()) {
    f.write(g + "/relaxation_metric", s.metric.positions, {s.metric.positions.size() / 3, 3});
    f.setAttribute(g + "/relaxation_metric", "kappa", s.metric.kappa);
    f.setAttribute(g + "/relaxation_metric", "shift", s.metric.shift);
    f.setAttribute(g + "/relaxation_metric", "outer_steps", s.metric.outer_steps);
  }
  MembraneState::fields(s, AttributeWriter{f, g});
  if (s.remeshing) {
    const SizingParameters& z = s.remeshing->sizing;
    f.write(g + "/remesh_sizing", std::vector<double>{z.flat_size, z.min_size, z.max_size, z.tolerance});
  }
  const RemeshStats& r = s.remesh_totals;
  f.write(g + "/remesh_totals", std::vector<std::int64_t>{r.sweeps, r.splits, r.collapses, r.flips, r.relocations});
  for (std::size_t k = 0; k < s.species.size(); ++k)
    f.write(g + "/species/" + s.species[k], std::vector<std::int32_t>(s.species_copies[k].begin(), s.species_copies[k].end()));
  if (!s.species.empty()) f.setAttribute(g + "/species", "order", joinColumns(s.species));
}

MembraneState readMembrane(const h5::File& f, const std::string& g, const std::string& file_name) {
  MembraneState s;
  const std::vector<double> x = f.readDoubles(g + "/vertices");
  for (std::size_t i = 0; i + 2 < x.size(); i += 3) s.mesh.positions.emplace_back(x[i], x[i + 1], x[i + 2]);
  const std::vector<std::int32_t> t = f.readInt32(g + "/triangles");
  for (std::size_t i = 0; i + 2 < t.size(); i += 3) s.mesh.triangles.push_back({t[i], t[i + 1], t[i + 2]});
  const std::vector<std::int8_t> fixed = f.readInt8(g + "/fixed");
  s.fixed.assign(fixed.begin(), fixed.end());
  s.material.vertex_area0 = f.readDoubles(g + "/vertex_area0");
  if (f.exists(g + "/relaxation_metric")) {  // absent before any relaxation (and in older checkpoints)
    s.metric.positions = f.readDoubles(g + "/relaxation_metric");
    s.metric.kappa = f.attributeDouble(g + "/relaxation_metric", "kappa");
    s.metric.shift = f.attributeDouble(g + "/relaxation_metric", "shift");
    s.metric.outer_steps = f.attributeInt64(g + "/relaxation_metric", "outer_steps");
  }
  MembraneState::fields(s, AttributeReader{f, g});
  if (f.exists(g + "/remesh_sizing")) {
    const std::vector<double> z = f.readDoubles(g + "/remesh_sizing");
    if (z.size() != 4) throw InputError(fmt::format("{}: {}/remesh_sizing is malformed", file_name, g));
    RemeshSettings rs;
    rs.sizing.flat_size = z[0], rs.sizing.min_size = z[1], rs.sizing.max_size = z[2], rs.sizing.tolerance = z[3];
    s.remeshing = rs;
  }
  if (!s.metric.positions.empty()) {
    if (s.metric.positions.size() != 3 * s.mesh.positions.size())
      throw InputError(fmt::format("{}: {}/relaxation_metric does not match the vertex count", file_name, g));
    const bool finite = std::all_of(s.metric.positions.begin(), s.metric.positions.end(),
                                    [](double x) { return std::isfinite(x); });
    if (!finite || !(s.metric.kappa > 0.0) || !(s.metric.shift > 0.0) || !std::isfinite(s.metric.kappa) ||
        !std::isfinite(s.metric.shift) || s.metric.outer_steps < 0)
      throw InputError(fmt::format("{}: {}/relaxation_metric is damaged (positions, kappa or shift not finite "
                                   "and positive)",
                                   file_name, g));
  }
  if (s.fixed.size() != s.mesh.positions.size() || s.material.vertex_area0.size() != s.mesh.positions.size())
    throw InputError(fmt::format("{}: {}: per-vertex arrays do not match the vertex count", file_name, g));
  const std::vector<std::int64_t> r = f.readInt64(g + "/remesh_totals");
  if (r.size() != 5) throw InputError(fmt::format("{}: {}/remesh_totals is malformed", file_name, g));
  s.remesh_totals = {r[1], r[2], r[3], r[4], r[0]};
  if (f.exists(g + "/species")) {
    s.species = f.attributeExists(g + "/species", "order") ? splitColumns(f.attributeString(g + "/species", "order"))
                                                           : f.children(g + "/species");
    for (const std::string& name : s.species) {
      const std::vector<std::int32_t> c = f.readInt32(g + "/species/" + name);
      if (c.size() != s.mesh.positions.size())
        throw InputError(fmt::format("{}: {}/species/{} does not match the vertex count", file_name, g, name));
      s.species_copies.emplace_back(c.begin(), c.end());
    }
  }
  return s;
}

void writeChemistry(h5::File& f, const ChemistryState& s) {
  const std::vector<std::int32_t> copies(s.copies.begin(), s.copies.end());
  const auto species = static_cast<hsize_t>(std::max<Index>(s.species, 1));
  f.write("/chemistry/copies", copies, {copies.size() / species, species});
  f.write("/chemistry/reaction_events", s.reaction_events);
  ChemistryState::fields(s, AttributeWriter{f, "/chemistry"});
}

ChemistryState readChemistry(const h5::File& f) {
  ChemistryState s;
  h5::Shape shape;
  const std::vector<std::int32_t> copies = f.readInt32("/chemistry/copies", &shape);
  s.copies.assign(copies.begin(), copies.end());
  s.species = shape.size() == 2 ? static_cast<Index>(shape[1]) : 0;
  s.reaction_events = f.readInt64("/chemistry/reaction_events");
  ChemistryState::fields(s, AttributeReader{f, "/chemistry"});
  return s;
}

}  // namespace

void writeCheckpoint(const std::filesystem::path& file, const CheckpointHeader& header, const SystemState& state) {
  std::string bytes;
  {
    h5::File f = h5::File::createInMemory(file);
    f.createGroups("/run");
    f.setAttribute("/run", "format", std::string(kFormat));
    f.setAttribute("/run", "config", header.config_toml);
    f.setAttribute("/run", "config_source", header.config_source);
    f.setAttribute("/run", "base_dir", header.base_dir);
    f.setAttribute("/run", "next_snapshot", header.next_snapshot);
    f.setAttribute("/run", "run_id", header.run_id);
    f.setAttribute("/run", "bodies", joinNames(state.bodies));
    SystemState::fields(state, AttributeWriter{f, "/run"});
    RunCounters::fields(state.counters, AttributeWriter{f, "/run"});
    for (const auto& [name, m] : state.membranes) writeMembrane(f, "/membranes/" + name, m);
    if (state.chemistry) writeChemistry(f, *state.chemistry);
    if (state.filaments) writeFilamentState(f, *state.filaments);
    bytes = std::string(kUserBlock, '\0') + f.image();
  }
  const std::string stamp = stampLine(bytes);
  bytes.replace(0, stamp.size(), stamp);
  writeFileAtomically(file, bytes);
}

namespace {

// readCheckpoint's body, on a file whose checksum holds.
Checkpoint readVerifiedCheckpoint(const std::filesystem::path& file) {
  h5::File f = h5::File::openReadOnly(file);
  if (!f.exists("/run") || f.attributeString("/run", "format") != kFormat)
    throw InputError(fmt::format("{}: not a cortex checkpoint (or from an incompatible version)", file.string()));
  Checkpoint cp;
  cp.header.config_toml = f.attributeString("/run", "config");
  cp.header.config_source = f.attributeString("/run", "config_source");
  cp.header.base_dir = f.attributeString("/run", "base_dir");
  cp.header.next_snapshot = f.attributeInt64("/run", "next_snapshot");
  cp.header.run_id = f.attributeString("/run", "run_id");
  SystemState& s = cp.state;
  s.bodies = splitNames(f.attributeString("/run", "bodies"));
  SystemState::fields(s, AttributeReader{f, "/run"});
  RunCounters::fields(s.counters, AttributeReader{f, "/run"});
  for (const std::string& name : f.exists("/membranes") ? f.children("/membranes") : std::vector<std::string>{})
    s.membranes.emplace(name, readMembrane(f, "/membranes/" + name, file.string()));
  if (f.exists("/chemistry")) s.chemistry = readChemistry(f);
  if (f.exists("/filaments")) s.filaments = readFilamentState(f, file.string());
  return cp;
}

}  // namespace

Checkpoint readCheckpoint(const std::filesystem::path& file) {
  if (!std::filesystem::exists(file))
    throw InputError(fmt::format("{}: no checkpoint to resume from", file.string()));
  verifyStamp(file);
  // The checksum catches damage; a file that passes it and still lacks a dataset or an
  // attribute (edited, or written by another version) is bad input all the same.
  try {
    return readVerifiedCheckpoint(file);
  } catch (const InputError&) {
    throw;
  } catch (const std::runtime_error& e) {
    throw InputError(fmt::format("{}: cannot be read as a checkpoint of this version ({}); start again with "
                                 "--overwrite",
                                 file.string(), e.what()));
  }
}

}  // namespace cortex
