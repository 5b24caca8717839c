// How a closed membrane cuts the compartment grid (thesis 2.2.4.2): per compartment the
// fraction of its volume inside the membrane and, per face, the fraction of the face's
// area inside. The engine scales hop rates and propensities by these (see
// ChemistryEngine::setConfinement).
//
// Compartments the membrane does not touch are wholly inside or outside: their centres
// are classified by casting one ray per grid column along +z, so the cost is
// O(columns x triangles) rather than O(compartments x triangles). A compartment the
// membrane cuts gets the thesis' planar approximation: the membrane parts inside it are
// replaced by one plane (through their area-weighted centroid, normal to their summed
// area vector), and the volume and face areas of the cube on the plane's inner side are
// computed exactly. A face shared by two compartments gets the mean of the two values,
// so that both sides see the same contact area (V_i d_ij stays symmetric).
#pragma once

#include <array>
#include <vector>

#include "chem/chemistry_model.hpp"

namespace cortex {

struct CompartmentSlices {
  std::vector<double> volume;                 // per compartment, inside fraction in [0, 1]
  std::vector<std::array<double, 6>> faces;   // per compartment, faces -x,+x,-y,+y,-z,+z
  std::vector<char> cut;                      // per compartment: 1 if the membrane cuts it
};

// `triangles` must form a closed mesh oriented with normals pointing outwards.
CompartmentSlices sliceCompartments(const std::vector<Vec3>& positions, const std::vector<Tri>& triangles,
                                    const CompartmentGrid& grid);

}  // namespace cortex
