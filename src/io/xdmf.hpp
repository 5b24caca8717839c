// The XDMF (version 2) description of a trajectory, so ParaView opens the whole time
// series; it points at the snapshot files (snapshots/NNNNNN.h5) directly.
// Pure text generation, kept apart from the writer so it can be tested without files.
#pragma once

#include <array>
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
  bool contact_force = false;  // the snapshot has /membranes/NAME/contact_force
  std::vector<std::string> species;  // /membranes/NAME/species/SPECIES, copies per vertex
};

// Element counts of a snapshot's filaments group; a grid with no elements is left out.
struct XdmfFilaments {
  std::int64_t beads = 0;
  std::int64_t cylinders = 0;
  std::int64_t linkers = 0;
  std::int64_t motors = 0;
  std::int64_t branch_points = 0;
  bool contact_force = false;  // the snapshot has /filaments/contact_force (per bead)
};

// The compartment grid of a snapshot: its shape and the species stored per compartment.
struct XdmfCompartments {
  std::array<std::int64_t, 3> shape{0, 0, 0};
  std::vector<std::string> species;
};

struct XdmfSnapshot {
  std::int64_t index = 0;  // the file snapshots/%06d.h5 (the group /snapshots/%06d of trajectory.h5)
  double time = 0.0;       // s
  std::vector<XdmfMembrane> membranes;
  std::optional<XdmfFilaments> filaments;
  std::optional<XdmfCompartments> compartments;
};

// "/snapshots/000042": where snapshot `index` appears in trajectory.h5.
std::string snapshotGroup(std::int64_t index);
// "snapshots/000042.h5": the file holding snapshot `index`, relative to the output folder.
std::string snapshotFile(std::int64_t index);

// "compartments.h5": the corner points of the compartment grid, written once per run
// (the grid does not move), relative to the output folder.
inline constexpr const char* kCompartmentPointsFile = "compartments.h5";

// The whole .xdmf document: one spatial collection holding one temporal collection per
// object, named by it, so each
// object keeps one name over all time steps (ParaView's "Xdmf Reader" shows one block per
// object; a reader would rename a name repeated inside one collection). Objects: one
// triangle grid per membrane (its name), 2-node polyline grids for filament cylinders
// ("filaments"), bound linkers ("linkers") and bound motors ("motors"), points for branch
// points ("branch_points"), and a structured grid whose cells are the compartments with
// one cell field per species ("compartments"). A time step where an object has no
// elements is left out of its collection (ParaView shows nothing there). Data paths are
// relative to the output folder, so the folder can be moved.
std::string trajectoryXdmf(const std::vector<XdmfSnapshot>& snapshots);

}  // namespace cortex
