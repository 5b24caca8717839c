// What the simulation loop hands to its writers at each snapshot: plain data, no
// physics objects, so writers (HDF5, XDMF, ...) know nothing of System.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace cortex {

// Copies of one species: of a 3D species per compartment, laid out as an (nx, ny, nz)
// C-order array; of a membrane species per vertex.
struct SpeciesField {
  std::string name;
  std::vector<std::int32_t> copies;
};

struct MembraneFrame {
  std::string name;
  std::vector<double> vertices;        // n*3, row-major (x0,y0,z0,x1,...), nm
  std::vector<std::int32_t> triangles; // m*3 vertex indices, counter-clockwise seen from outside
  std::vector<double> mean_curvature;  // n, 1/nm
  // n*3, pN: the force the filaments put on each vertex (membrane–bead excluded volume);
  // empty in runs where membranes and filaments do not interact.
  std::vector<double> contact_force;
  // Copies of each membrane species per vertex (n each); empty without species.
  std::vector<SpeciesField> species;
};

// The cytoskeleton, flattened. Filament i (its index, an identity for the whole run) owns
// beads offsets[i]..offsets[i+1]-1; a cylinder is a pair of consecutive bead indices.
// Linkers and motors are given by the positions of their two bound ends.
struct FilamentFrame {
  std::vector<double> beads;                   // k*3, nm
  std::vector<std::int64_t> offsets{0};        // f+1
  std::vector<std::int64_t> ids;               // f
  std::vector<std::int32_t> types;             // f, filament type index
  std::vector<double> lengths;                 // f, nm
  std::vector<std::int64_t> monomers;          // f
  std::vector<std::int32_t> cylinders;         // m*2 bead indices
  std::vector<std::int32_t> cylinder_filament; // m, filament id of each cylinder
  std::vector<double> linkers;                 // n*6: end 0 (x,y,z), end 1 (x,y,z), nm
  std::vector<std::int32_t> linker_types;      // n
  std::vector<double> linker_tensions;         // n, pN
  std::vector<double> motors;                  // n*6
  std::vector<std::int32_t> motor_types;       // n
  std::vector<double> motor_tensions;          // n, pN
  std::vector<double> branch_points;           // b*3, nm: each daughter's first bead
  // k*3, pN: the force every contact term (walls, excluded volume, membranes) puts on
  // each bead, the ratchet's load at the ends; empty unless membranes and filaments interact.
  std::vector<double> contact_force;
  // Names of the type indices above: filament, linker and motor types.
  std::vector<std::string> type_names, linker_type_names, motor_type_names;
};


// Scalar observables of one snapshot, one named column each (io/observables.hpp).
struct ObservableRow {
  std::vector<std::string> names;
  std::vector<double> values;
};

struct Frame {
  double time = 0.0;       // s
  std::int64_t step = 0;   // chemistry windows completed
  ObservableRow observables;
  std::vector<MembraneFrame> membranes;
  std::array<std::int64_t, 3> grid_shape{0, 0, 0};
  double grid_spacing = 0.0;  // nm, the compartments' edge; the grid starts at the origin
  std::vector<SpeciesField> compartment_species;
  std::optional<FilamentFrame> filaments;  // set when the run has a filament network
};

// The loop in sim/ calls write() at every snapshot; implementations live in io/.
class FrameWriter {
 public:
  virtual ~FrameWriter() = default;
  virtual void write(const Frame& frame) = 0;
};

}  // namespace cortex
