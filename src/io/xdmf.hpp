// The XDMF (version 2) description of a trajectory, so ParaView opens the whole time
// series; it points at the snapshot files (snapshots/NNNNNN.h5) directly.
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
  std::int64_t index = 0;  // the file snapshots/%06d.h5 (the group /snapshots/%06d of trajectory.h5)
  double time = 0.0;       // s
  std::vector<XdmfMembrane> membranes;
  std::optional<XdmfFilaments> filaments;
};

// "/snapshots/000042": where snapshot `index` appears in trajectory.h5.
std::string snapshotGroup(std::int64_t index);
// "snapshots/000042.h5": the file holding snapshot `index`, relative to the output folder.
std::string snapshotFile(std::int64_t index);

// The whole .xdmf document: a temporal collection of per-snapshot spatial collections,
// one triangle grid per membrane, and 2-node polyline grids for filament cylinders
// ("filaments"), bound linkers ("linkers") and bound motors ("motors"). Data paths are
// relative to the output folder, so the folder can be moved.
std::string trajectoryXdmf(const std::vector<XdmfSnapshot>& snapshots);

}  // namespace cortex
