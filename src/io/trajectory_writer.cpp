#include "io/trajectory_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>

#include "core/error.hpp"
#include "io/hdf5_file.hpp"

namespace cortex {
namespace {

constexpr const char* kH5Name = "trajectory.h5";  // the XDMF refers to it by this relative name

// A snapshot group's name, or -1 for anything else found under /snapshots.
std::int64_t parseIndex(const std::string& name) {
  const bool digits = !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
    return c >= '0' && c <= '9';
  });
  return digits ? std::stoll(name) : -1;
}

// Rebuilds the XDMF description of a snapshot already in the file (for a resumed run).
XdmfSnapshot describe(const h5::File& file, std::int64_t index) {
  const std::string group = snapshotGroup(index);
  XdmfSnapshot snapshot{index, file.attributeDouble(group, "time"), {}, std::nullopt};
  const std::string filaments = group + "/filaments";
  if (file.exists(filaments)) {
    const auto rows = [&](const char* dataset) {
      return static_cast<std::int64_t>(file.shape(filaments + dataset).at(0));
    };
    snapshot.filaments = XdmfFilaments{rows("/beads"), rows("/cylinders"), rows("/linkers"), rows("/motors")};
  }
  const std::string membranes = group + "/membranes";
  if (!file.exists(membranes)) return snapshot;
  for (const std::string& name : file.children(membranes)) {
    const std::string path = membranes + "/" + name;
    const auto rows = [&](const char* dataset) {
      return static_cast<std::int64_t>(file.shape(path + dataset).at(0));
    };
    snapshot.membranes.push_back({name, rows("/vertices"), rows("/triangles")});
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
  return {name, static_cast<std::int64_t>(n), static_cast<std::int64_t>(m)};
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
      f.offsets.back() == static_cast<std::int64_t>(k);
  if (!consistent) {
    throw RunError(fmt::format("inconsistent filament frame ({} bead coordinates, {} offsets, {} ids, {} "
                               "cylinder indices, {} linker coordinates, {} motor coordinates)",
                               f.beads.size(), f.offsets.size(), n, f.cylinders.size(), f.linkers.size(),
                               f.motors.size()));
  }
  const std::string path = group + "/filaments/";
  file.write(path + "beads", f.beads, {k, 3});
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
  return {static_cast<std::int64_t>(k), static_cast<std::int64_t>(m), static_cast<std::int64_t>(nl),
          static_cast<std::int64_t>(nm)};
}

}  // namespace

TrajectoryWriter::TrajectoryWriter(std::filesystem::path outdir, std::int64_t first_index,
                                   bool append)
    : outdir_(std::move(outdir)), next_index_(first_index) {
  h5::File file = append ? h5::File::openReadWrite(h5Path()) : h5::File::create(h5Path());
  if (file.exists("/snapshots")) {
    for (const std::string& name : file.children("/snapshots")) {
      const std::int64_t index = parseIndex(name);
      if (index < 0) continue;
      if (index >= first_index) {
        file.remove("/snapshots/" + name);
      } else {
        snapshots_.push_back(describe(file, index));
      }
    }
  }
  file.createGroups("/snapshots");
  file.flush();
  // Names sort as numbers only up to 999999; the XDMF must list snapshots in time order.
  std::sort(snapshots_.begin(), snapshots_.end(),
            [](const XdmfSnapshot& a, const XdmfSnapshot& b) { return a.index < b.index; });
  // Also replaces any XDMF a previous run left here, which would point at deleted snapshots.
  writeXdmf();
}

void TrajectoryWriter::write(const Frame& frame) {
  XdmfSnapshot snapshot{next_index_, frame.time, {}, std::nullopt};
  {
    // The file existed since construction; losing it mid-run is a run failure, not bad input.
    h5::File file = [&] {
      try {
        return h5::File::openReadWrite(h5Path());
      } catch (const InputError& e) {
        throw RunError(e.what());
      }
    }();
    const std::string group = snapshotGroup(next_index_);
    file.createGroups(group);
    file.setAttribute(group, "time", frame.time);
    file.setAttribute(group, "step", frame.step);
    for (const MembraneFrame& membrane : frame.membranes) {
      snapshot.membranes.push_back(writeMembrane(file, group, membrane));
    }
    const h5::Shape grid(frame.grid_shape.begin(), frame.grid_shape.end());
    for (const SpeciesField& field : frame.compartment_species)
      file.write(group + "/compartments/species/" + field.name, field.copies, grid);
    if (frame.filaments) snapshot.filaments = writeFilaments(file, group, *frame.filaments);
    file.flush();
  }  // the file closes here
  snapshots_.push_back(std::move(snapshot));
  ++next_index_;
  writeXdmf();
}

std::filesystem::path TrajectoryWriter::h5Path() const { return outdir_ / kH5Name; }

void TrajectoryWriter::writeXdmf() const {
  // Write-then-rename, so a reader (or a crash) never sees a half-written XDMF.
  const std::filesystem::path target = outdir_ / "trajectory.xdmf";
  const std::filesystem::path temp = outdir_ / "trajectory.xdmf.tmp";
  {
    std::ofstream out(temp, std::ios::binary | std::ios::trunc);
    out << trajectoryXdmf(snapshots_, kH5Name);
    out.close();
    if (!out) throw RunError(fmt::format("cannot write '{}'", temp.string()));
  }
  std::error_code error;
  std::filesystem::rename(temp, target, error);
  if (error) {
    throw RunError(fmt::format("cannot rename '{}' to '{}': {}", temp.string(), target.string(),
                               error.message()));
  }
}

}  // namespace cortex
