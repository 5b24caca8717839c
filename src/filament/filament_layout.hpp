// What the filament energy terms read: the network flattened, for one minimization, into
// beads in the minimizer's coordinate vector and lists of the elements between them.
// Rebuilt by FilamentNetwork::layOut whenever chemistry changed the network; positions
// are never stored here (they are in the coordinate vector), only indices and constants.
#pragma once

#include <cstdint>
#include <vector>

#include "core/types.hpp"

namespace cortex {

// Bead b's coordinates are x[3 * (bead_offset + b)], ...: filament beads follow the
// membrane vertices in the minimizer's vector.
struct Cylinder {
  Index bead0, bead1;     // minus-side and plus-side bead (layout numbering)
  Index filament;         // index into FilamentNetwork::filaments()
  Index type;             // FilamentType index
  double rest_length;     // nm: monomers * monomer_size
};

// Two consecutive cylinders bead0->bead1->bead2 of one filament.
struct Hinge {
  Index bead0, bead1, bead2;
  Index type;
};

// A point on a cylinder: (1 - w) * x[bead0] + w * x[bead1].
struct CylinderPoint {
  Index bead0, bead1;
  double w;
};

// A spring between points on two cylinders (linkers, motors): E = k/2 (|pb - pa| - l0)^2.
struct Spring {
  CylinderPoint a, b;
  double stiffness, rest_length;
};

// A branch: the daughter's minus-end bead is held at a point of the mother cylinder
// (E = k_p/2 |x_d - p|^2) and its first cylinder at angle theta0 to the mother cylinder
// (E = K (cos theta - cos theta0)^2, cos theta between mother bead0->bead1 and daughter
// bead d0->d1).
struct BranchJoint {
  CylinderPoint mother;
  Index daughter0, daughter1;
  double position_stiffness, angle_stiffness, cos_angle;
};

struct FilamentLayout {
  std::uint64_t version = 0;  // changes whenever the lists below change
  Index bead_offset = 0;
  Index num_beads = 0;
  std::vector<Cylinder> cylinders;
  std::vector<Hinge> hinges;
  std::vector<Spring> linkers, motors;
  std::vector<BranchJoint> branches;
};

}  // namespace cortex
