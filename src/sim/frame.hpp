// What the simulation loop hands to its writers at each snapshot: plain data, no
// physics objects, so writers (HDF5, XDMF, ...) know nothing of System.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace cortex {

struct MembraneFrame {
  std::string name;
  std::vector<double> vertices;        // n*3, row-major (x0,y0,z0,x1,...), nm
  std::vector<std::int32_t> triangles; // m*3 vertex indices, counter-clockwise seen from outside
  std::vector<double> mean_curvature;  // n, 1/nm
};

// Copies of one 3D species per compartment, laid out as an (nx, ny, nz) C-order array.
struct SpeciesField {
  std::string name;
  std::vector<std::int32_t> copies;
};

struct Frame {
  double time = 0.0;       // s
  std::int64_t step = 0;   // chemistry windows completed
  std::vector<MembraneFrame> membranes;
  std::array<std::int64_t, 3> grid_shape{0, 0, 0};
  std::vector<SpeciesField> compartment_species;
};

// The loop in sim/ calls write() at every snapshot; implementations live in io/.
class FrameWriter {
 public:
  virtual ~FrameWriter() = default;
  virtual void write(const Frame& frame) = 0;
};

}  // namespace cortex
