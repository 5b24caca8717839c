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
  XdmfSnapshot snapshot{index, file.attributeDouble(group, "time"), {}};
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
  XdmfSnapshot snapshot{next_index_, frame.time, {}};
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
