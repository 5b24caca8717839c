// The XDMF (version 2) index of trajectory.h5, so ParaView opens the whole time series.
// Pure text generation, kept apart from the writer so it can be tested without files.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace cortex {

// Enough about one membrane in one snapshot to point XDMF at its datasets.
struct XdmfMembrane {
  std::string name;
  std::int64_t vertices = 0;
  std::int64_t triangles = 0;
};

// Element counts of a snapshot's filaments group; a grid with no elements is left out.
struct XdmfFilaments {
  std::int64_t beads = 0;
  std::int64_t cylinders = 0;
  std::int64_t linkers = 0;
  std::int64_t motors = 0;
};

struct XdmfSnapshot {
  std::int64_t index = 0;  // the group /snapshots/%06d in trajectory.h5
  double time = 0.0;       // s
  std::vector<XdmfMembrane> membranes;
  std::optional<XdmfFilaments> filaments;
};

// "/snapshots/000042": where snapshot `index` lives in trajectory.h5.
std::string snapshotGroup(std::int64_t index);

// The whole .xdmf document: a temporal collection of per-snapshot spatial collections,
// one triangle grid per membrane, and 2-node polyline grids for filament cylinders
// ("filaments"), bound linkers ("linkers") and bound motors ("motors"). `h5_name` is the HDF5 file's path relative to the .xdmf
// (just the file name, so the output folder can be moved).
std::string trajectoryXdmf(const std::vector<XdmfSnapshot>& snapshots, const std::string& h5_name);

}  // namespace cortex
