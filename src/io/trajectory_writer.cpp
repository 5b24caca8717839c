#include "io/trajectory_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <optional>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/hdf5_file.hpp"

namespace cortex {
namespace {

// The index of a snapshot file "NNNNNN.h5", or -1 for any other name.
std::int64_t parseIndex(const std::string& name) {
  if (name.size() != 9 || name.compare(6, 3, ".h5") != 0) return -1;
  const bool digits = std::all_of(name.begin(), name.begin() + 6, [](char c) { return c >= '0' && c <= '9'; });
  return digits ? std::stoll(name.substr(0, 6)) : -1;
}

constexpr const char* kIndexName = "trajectory.h5";
constexpr const char* kIndexFormat = "cortex trajectory 2";

constexpr const char* kUnits =
    "length nm, time s, force pN, energy pN nm, tension pN/nm, pressure pN/nm^2, concentration uM, diffusion nm^2/s";

// The observables a snapshot file holds (none in files of runs without them).
ObservableRow observablesOf(const h5::File& file) {
  ObservableRow row;
  if (!file.exists("/observables")) return row;
  row.names = splitColumns(file.attributeString("/observables", "columns"));
  row.values = file.readDoubles("/observables");
  if (row.names.size() != row.values.size()) throw std::runtime_error("observables and their columns differ in count");
  return row;
}

// Names joined by commas, as attributes store them (names hold no comma: config names are
// validated).
std::vector<std::string> splitNames(const h5::File& file, const std::string& object, const char* attribute) {
  return file.attributeExists(object, attribute) ? splitColumns(file.attributeString(object, attribute))
                                                 : std::vector<std::string>{};
}

// The compartment species of a snapshot file in the config's order (its attribute), not
// HDF5's alphabetical one, so a resumed run describes them as the first run did.
std::vector<std::string> speciesOf(const h5::File& file) {
  return file.attributeExists("/compartments", "species") ? splitNames(file, "/compartments", "species")
                                                          : file.children("/compartments/species");
}

// The names a snapshot file holds (for a resumed run's index).
DatasetNames namesOf(const h5::File& file) {
  DatasetNames names;
  if (file.exists("/compartments/species")) {
    names.species = speciesOf(file);
    if (!names.species.empty()) {
      for (const hsize_t n : file.shape("/compartments/species/" + names.species.front()))
        names.compartment_shape.push_back(static_cast<std::int64_t>(n));
    }
    if (file.attributeExists("/compartments", "size")) names.compartment_size = file.attributeDouble("/compartments", "size");
  }
  names.filament_types = splitNames(file, "/filaments", "type_names");
  names.linker_types = splitNames(file, "/filaments", "linker_type_names");
  names.motor_types = splitNames(file, "/filaments", "motor_type_names");
  return names;
}

// The XDMF description of a snapshot file already written (for a resumed run).
XdmfSnapshot describe(const h5::File& file, std::int64_t index) {
  XdmfSnapshot snapshot{index, file.attributeDouble("/", "time"), {}, std::nullopt, std::nullopt};
  if (file.exists("/filaments")) {
    const auto rows = [&](const char* dataset) {
      return static_cast<std::int64_t>(file.shape(std::string("/filaments") + dataset).at(0));
    };
    snapshot.filaments = XdmfFilaments{rows("/beads"),  rows("/cylinders"),     rows("/linkers"),
                                       rows("/motors"), rows("/branch_points"), file.exists("/filaments/contact_force")};
  }
  if (file.exists("/compartments/species")) {
    XdmfCompartments& c = snapshot.compartments.emplace();
    c.species = speciesOf(file);
    if (!c.species.empty()) {
      const h5::Shape shape = file.shape("/compartments/species/" + c.species.front());
      for (std::size_t a = 0; a < 3; ++a) c.shape[a] = static_cast<std::int64_t>(shape.at(a));
    }
  }
  if (!file.exists("/membranes")) return snapshot;
  for (const std::string& name : file.children("/membranes")) {
    const std::string path = "/membranes/" + name;
    const auto rows = [&](const char* dataset) {
      return static_cast<std::int64_t>(file.shape(path + dataset).at(0));
    };
    std::vector<std::string> species;
    if (file.exists(path + "/species"))
      species = file.attributeExists(path + "/species", "order") ? splitNames(file, path + "/species", "order")
                                                                 : file.children(path + "/species");
    snapshot.membranes.push_back(
        {name, rows("/vertices"), rows("/triangles"), file.exists(path + "/contact_force"), species});
  }
  return snapshot;
}

XdmfMembrane writeMembrane(h5::File& file, const std::string& group,
                           const MembraneFrame& membrane) {
  // The name becomes an HDF5 group and part of an XDMF "file:/path" reference.
  const std::string& name = membrane.name;
  if (name.empty() || name == "." || name.find('/') != std::string::npos) {
    throw InputError(fmt::format("membrane name '{}' cannot name an HDF5 group", name));
  }
  const std::size_t n = membrane.vertices.size() / 3;
  const std::size_t m = membrane.triangles.size() / 3;
  if (membrane.vertices.size() != 3 * n || membrane.triangles.size() != 3 * m ||
      membrane.mean_curvature.size() != n) {
    throw RunError(fmt::format("membrane '{}': inconsistent frame ({} vertex coordinates, {} "
                               "triangle indices, {} curvatures)",
                               name, membrane.vertices.size(), membrane.triangles.size(),
                               membrane.mean_curvature.size()));
  }
  const std::string path = group + "/membranes/" + name;
  file.write(path + "/vertices", membrane.vertices, {n, 3});
  file.write(path + "/triangles", membrane.triangles, {m, 3});
  file.write(path + "/mean_curvature", membrane.mean_curvature, {n});
  const bool forces = !membrane.contact_force.empty();
  if (forces) {
    if (membrane.contact_force.size() != 3 * n)
      throw RunError(fmt::format("membrane '{}': {} contact force components for {} vertices", name,
                                 membrane.contact_force.size(), n));
    file.write(path + "/contact_force", membrane.contact_force, {n, 3});
  }
  std::vector<std::string> species;
  for (const SpeciesField& field : membrane.species) {
    if (field.copies.size() != n)
      throw RunError(fmt::format("membrane '{}': {} copies of species '{}' for {} vertices", name, field.copies.size(),
                                 field.name, n));
    file.write(path + "/species/" + field.name, field.copies, {n});
    species.push_back(field.name);
  }
  if (!species.empty()) file.setAttribute(path + "/species", "order", joinColumns(species));
  return {name, static_cast<std::int64_t>(n), static_cast<std::int64_t>(m), forces, species};
}

// Segment i joins rows 2i and 2i+1 of an (n,2,3) end-position dataset read as (2n,3).
std::vector<std::int32_t> pairCells(std::size_t n) {
  std::vector<std::int32_t> cells(2 * n);
  for (std::size_t i = 0; i < cells.size(); ++i) cells[i] = static_cast<std::int32_t>(i);
  return cells;
}

// Every dataset is written even when empty, so readers need no special cases.
XdmfFilaments writeFilaments(h5::File& file, const std::string& group, const FilamentFrame& f) {
  const std::size_t k = f.beads.size() / 3, n = f.ids.size(), m = f.cylinders.size() / 2;
  const std::size_t nl = f.linker_types.size(), nm = f.motor_types.size(), b = f.branch_points.size() / 3;
  const bool consistent =
      f.beads.size() == 3 * k && f.offsets.size() == n + 1 && f.types.size() == n && f.lengths.size() == n &&
      f.monomers.size() == n && f.cylinders.size() == 2 * m && f.cylinder_filament.size() == m &&
      f.linkers.size() == 6 * nl && f.linker_tensions.size() == nl && f.motors.size() == 6 * nm &&
      f.motor_tensions.size() == nm && f.branch_points.size() == 3 * b &&
      f.offsets.back() == static_cast<std::int64_t>(k) && (f.contact_force.empty() || f.contact_force.size() == 3 * k);
  if (!consistent) {
    throw RunError(fmt::format("inconsistent filament frame ({} bead coordinates, {} offsets, {} ids, {} "
                               "cylinder indices, {} linker coordinates, {} motor coordinates)",
                               f.beads.size(), f.offsets.size(), n, f.cylinders.size(), f.linkers.size(),
                               f.motors.size()));
  }
  const std::string path = group + "/filaments/";
  file.write(path + "beads", f.beads, {k, 3});
  file.setAttribute(group + "/filaments", "type_names", joinColumns(f.type_names));
  file.setAttribute(group + "/filaments", "linker_type_names", joinColumns(f.linker_type_names));
  file.setAttribute(group + "/filaments", "motor_type_names", joinColumns(f.motor_type_names));
  file.write(path + "offsets", f.offsets, {n + 1});
  file.write(path + "ids", f.ids, {n});
  file.write(path + "types", f.types, {n});
  file.write(path + "lengths", f.lengths, {n});
  file.write(path + "monomers", f.monomers, {n});
  file.write(path + "cylinders", f.cylinders, {m, 2});
  file.write(path + "cylinder_filament", f.cylinder_filament, {m});
  file.write(path + "linkers", f.linkers, {nl, 2, 3});
  file.write(path + "linker_types", f.linker_types, {nl});
  file.write(path + "linker_tensions", f.linker_tensions, {nl});
  file.write(path + "linker_cells", pairCells(nl), {nl, 2});
  file.write(path + "motors", f.motors, {nm, 2, 3});
  file.write(path + "motor_types", f.motor_types, {nm});
  file.write(path + "motor_tensions", f.motor_tensions, {nm});
  file.write(path + "motor_cells", pairCells(nm), {nm, 2});
  file.write(path + "branch_points", f.branch_points, {b, 3});
  if (!f.contact_force.empty()) file.write(path + "contact_force", f.contact_force, {k, 3});
  return {static_cast<std::int64_t>(k), static_cast<std::int64_t>(m), static_cast<std::int64_t>(nl),
          static_cast<std::int64_t>(nm), static_cast<std::int64_t>(b), !f.contact_force.empty()};
}

}  // namespace

void TrajectoryWriter::checkResumable(const std::filesystem::path& outdir, std::int64_t first_index,
                                      const std::string& run_id, double checkpoint_time) {
  const auto refuse = [&](const std::string& why) {
    throw InputError(fmt::format("{}: cannot resume the trajectory: {}; start again with --overwrite", outdir.string(),
                                 why));
  };
  if (first_index < 1)
    refuse(fmt::format("checkpoint.h5 counts {} snapshots written before it, where a run writes snapshot 0 before "
                       "its first checkpoint (checkpoint.h5 edited?)",
                       first_index));
  std::vector<std::int64_t> kept;   // indices of the snapshots the checkpoint counts
  std::optional<double> next_time;  // of snapshot first_index, if there
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(outdir / "snapshots", ec)) {
    const std::int64_t index = parseIndex(entry.path().filename().string());
    if (index < 0 || index > first_index) continue;
    try {
      const h5::File file = h5::File::openReadOnly(entry.path());
      if (index == first_index) {
        next_time = file.attributeDouble("/", "time");
        continue;
      }
      // Snapshots carry the run's id: a checkpoint and trajectory copied in from another
      // run of the same config resumed to exit 0 behind this run's snapshots. (Files of
      // versions before the id have none, and are taken as they are.)
      if (file.attributeExists("/", "run_id") && file.attributeString("/", "run_id") != run_id)
        refuse(fmt::format("snapshot file '{}' belongs to another run than checkpoint.h5 and trajectory.h5 (files "
                           "copied in from another run?)",
                           entry.path().string()));
      if (index == first_index - 1 && !(file.attributeDouble("/", "time") <= checkpoint_time))
        refuse(fmt::format("snapshot file '{}' is of t = {:g} s, after the checkpoint's t = {:g} s (checkpoint.h5 "
                           "edited?)",
                           entry.path().string(), file.attributeDouble("/", "time"), checkpoint_time));
    } catch (const InputError&) {
      throw;
    } catch (const std::runtime_error& e) {
      refuse(fmt::format("snapshot file '{}' is unreadable ({})", entry.path().string(), e.what()));
    }
    kept.push_back(index);
  }
  if (ec) refuse(fmt::format("its snapshots folder cannot be read ({})", ec.message()));
  // The checkpoint was written after the snapshots it counts and before the next one: a
  // count edited down deleted the later snapshots and renumbered the rest, with exit 0.
  if (next_time && !(*next_time > checkpoint_time))
    refuse(fmt::format("checkpoint.h5 counts {} snapshots written before it, but snapshot {} is of t = {:g} s, not "
                       "after the checkpoint's t = {:g} s (checkpoint.h5 edited?)",
                       first_index, first_index, *next_time, checkpoint_time));
  // The checkpoint continues snapshots 0 .. first_index - 1: a resume without some of them
  // ended with exit 0 and a trajectory silently missing those times. (Found from the
  // files there, not by listing all first_index names: the count may be edited.)
  if (static_cast<std::int64_t>(kept.size()) != first_index) {
    std::sort(kept.begin(), kept.end());
    std::int64_t first_missing = 0;
    while (first_missing < static_cast<std::int64_t>(kept.size()) && kept[first_missing] == first_missing)
      ++first_missing;
    const std::int64_t missing = first_index - static_cast<std::int64_t>(kept.size());
    refuse(fmt::format("{} of the {} snapshot files before the checkpoint are missing ({}{}); put them back",
                       missing, first_index, snapshotFile(first_missing), missing > 1 ? ", ..." : ""));
  }
}

TrajectoryWriter::TrajectoryWriter(std::filesystem::path outdir, std::int64_t first_index, bool append,
                                   std::string run_id, std::string config_toml)
    : outdir_(std::move(outdir)),
      next_index_(first_index),
      run_id_(std::move(run_id)),
      config_toml_(std::move(config_toml)) {
  const std::filesystem::path folder = outdir_ / "snapshots";
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  if (ec) throw RunError(fmt::format("cannot create '{}': {}", folder.string(), ec.message()));
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    const std::int64_t index = parseIndex(name);
    // Later snapshots are written again; temporary files are what a crash left.
    if (!append || index < 0 || index >= first_index) {
      if (index >= 0 || name.ends_with(".tmp")) std::filesystem::remove(entry.path(), ec);
      continue;
    }
    try {
      const h5::File file = h5::File::openReadOnly(entry.path());
      snapshots_.push_back(describe(file, index));
      rows_.push_back(observablesOf(file));
      if (index == first_index - 1) names_ = namesOf(file);
    } catch (const std::runtime_error& e) {
      throw InputError(fmt::format("cannot resume the trajectory: snapshot file '{}' is unreadable ({})",
                                   entry.path().string(), e.what()));
    }
  }
  // The XDMF and the table list snapshots in time order (directory order is arbitrary).
  std::vector<std::size_t> order(snapshots_.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return snapshots_[a].index < snapshots_[b].index; });
  std::vector<XdmfSnapshot> snapshots;
  std::vector<ObservableRow> rows;
  for (std::size_t i : order) snapshots.push_back(std::move(snapshots_[i])), rows.push_back(std::move(rows_[i]));
  snapshots_.swap(snapshots);
  rows_.swap(rows);
  writeIndex();
}

void TrajectoryWriter::write(const Frame& frame) {
  XdmfSnapshot snapshot{next_index_, frame.time, {}, std::nullopt, std::nullopt};
  const std::filesystem::path path = outdir_ / snapshotFile(next_index_);
  std::string bytes;
  {
    h5::File file = h5::File::createInMemory(path);
    file.setAttribute("/", "time", frame.time);
    file.setAttribute("/", "step", frame.step);
    file.setAttribute("/", "run_id", run_id_);
    for (const MembraneFrame& membrane : frame.membranes) snapshot.membranes.push_back(writeMembrane(file, "", membrane));
    const h5::Shape grid(frame.grid_shape.begin(), frame.grid_shape.end());
    DatasetNames names;
    if (!frame.compartment_species.empty()) {
      XdmfCompartments& c = snapshot.compartments.emplace();
      c.shape = frame.grid_shape;
      for (const SpeciesField& field : frame.compartment_species) {
        file.write("/compartments/species/" + field.name, field.copies, grid);
        c.species.push_back(field.name);
      }
      file.setAttribute("/compartments", "size", frame.grid_spacing);
      file.setAttribute("/compartments", "species", joinColumns(c.species));
      names.compartment_size = frame.grid_spacing;
      names.compartment_shape.assign(frame.grid_shape.begin(), frame.grid_shape.end());
      names.species = c.species;
    }
    if (frame.filaments) {
      snapshot.filaments = writeFilaments(file, "", *frame.filaments);
      names.filament_types = frame.filaments->type_names;
      names.linker_types = frame.filaments->linker_type_names;
      names.motor_types = frame.filaments->motor_type_names;
    }
    names_ = std::move(names);
    if (!frame.observables.names.empty()) {
      file.write("/observables", frame.observables.values);
      file.setAttribute("/observables", "columns", joinColumns(frame.observables.names));
    }
    bytes = file.image();
  }
  writeFileAtomically(path, bytes);
  if (snapshot.compartments && !compartment_points_written_) writeCompartmentPoints(frame);
  snapshots_.push_back(std::move(snapshot));
  rows_.push_back(frame.observables);
  ++next_index_;
  constexpr std::size_t kAlwaysIndexed = 100;
  constexpr double kIndexShare = 0.05;  // of the wall time, at most
  if (snapshots_.size() <= kAlwaysIndexed ||
      std::chrono::duration<double>(std::chrono::steady_clock::now() - index_written_).count() * kIndexShare >=
          index_seconds_)
    writeIndex();
}

void TrajectoryWriter::flush() {
  if (indexed_ != snapshots_.size()) writeIndex();
}

// The index first, then the XDMF: each is whole or absent, and both list only snapshot
// files that are whole.
void TrajectoryWriter::writeIndex() {
  const auto start = std::chrono::steady_clock::now();
  std::string bytes, csv;
  {
    h5::File index = h5::File::createInMemory(outdir_ / kIndexName);
    index.setAttribute("/", "format", std::string(kIndexFormat));
    index.setAttribute("/", "run_id", run_id_);
    index.setAttribute("/", "cortex_version", std::string(CORTEX_VERSION));
    index.setAttribute("/", "units", std::string(kUnits));
    index.setAttribute("/", "config", config_toml_);
    if (!names_.compartment_shape.empty()) {
      index.setAttribute("/", "compartment_size", names_.compartment_size);
      index.setAttribute("/", "compartment_shape", names_.compartment_shape);
      index.setAttribute("/", "species", joinColumns(names_.species));
    }
    if (!names_.filament_types.empty()) {
      index.setAttribute("/", "filament_types", joinColumns(names_.filament_types));
      index.setAttribute("/", "linker_types", joinColumns(names_.linker_types));
      index.setAttribute("/", "motor_types", joinColumns(names_.motor_types));
    }
    index.createGroups("/snapshots");
    for (const XdmfSnapshot& s : snapshots_) index.linkExternal(snapshotGroup(s.index), snapshotFile(s.index), "/");
    const ObservableTable table = tabulate(rows_);
    if (!table.columns.empty()) {
      index.write("/observables", table.values, {table.rows, table.columns.size()});
      index.setAttribute("/observables", "columns", joinColumns(table.columns));
    }
    csv = observablesCsv(table);
    bytes = index.image();
  }
  writeFileAtomically(outdir_ / kIndexName, bytes);
  writeFileAtomically(outdir_ / "observables.csv", csv);
  writeFileAtomically(outdir_ / "trajectory.xdmf", trajectoryXdmf(snapshots_));
  indexed_ = snapshots_.size();
  index_written_ = std::chrono::steady_clock::now();
  index_seconds_ = std::chrono::duration<double>(index_written_ - start).count();
}

// Corner (i, j, k) of the grid at (i, j, k) times the compartment size, in C order (k
// fastest) like the species datasets; a structured grid over them has the compartments as
// cells in the datasets' order.
void TrajectoryWriter::writeCompartmentPoints(const Frame& frame) {
  const auto [nx, ny, nz] = frame.grid_shape;
  std::vector<double> points;
  points.reserve(static_cast<std::size_t>(3 * (nx + 1) * (ny + 1) * (nz + 1)));
  for (std::int64_t i = 0; i <= nx; ++i)
    for (std::int64_t j = 0; j <= ny; ++j)
      for (std::int64_t k = 0; k <= nz; ++k)
        points.insert(points.end(), {static_cast<double>(i) * frame.grid_spacing, static_cast<double>(j) * frame.grid_spacing,
                                     static_cast<double>(k) * frame.grid_spacing});
  const std::filesystem::path path = outdir_ / kCompartmentPointsFile;
  std::string bytes;
  {
    h5::File file = h5::File::createInMemory(path);
    file.write("/points", points, {points.size() / 3, 3});
    file.setAttribute("/", "size", frame.grid_spacing);
    file.setAttribute("/", "shape", std::vector<std::int64_t>(frame.grid_shape.begin(), frame.grid_shape.end()));
    bytes = file.image();
  }
  writeFileAtomically(path, bytes);
  compartment_points_written_ = true;
}

std::string trajectoryRunId(const std::filesystem::path& outdir) {
  try {
    const h5::File index = h5::File::openReadOnly(outdir / kIndexName);
    return index.attributeString("/", "run_id");
  } catch (const std::runtime_error&) {
    return "";
  }
}

}  // namespace cortex
