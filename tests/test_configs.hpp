// Configs written in C++, as the tests build their Systems (no TOML involved).
#pragma once

#include <string>

#include "mesh/surface_mesh.hpp"
#include "sim/run_config.hpp"

namespace cortex::testing {

// A membrane whose initial mesh is `mesh` itself.
inline MembraneConfig membraneOf(const std::string& name, const SurfaceMesh& mesh, const MembraneMechanics& mechanics) {
  MembraneConfig c;
  c.name = name;
  c.shape = "mesh";
  c.soup = TriangleSoup{mesh.positions(), mesh.triangles()};
  c.mechanics = mechanics;
  return c;
}

inline Config configWith(std::vector<MembraneConfig> membranes) {
  Config c;
  c.source = "test config";
  c.membranes = std::move(membranes);
  return c;
}

// κ = 100 pN·nm, global area 400 pN/nm, volume 0.8 pN/nm^2 (the thesis' values).
inline MembraneMechanics vesicleMechanics(double reduced_volume) {
  MembraneMechanics m;
  m.bending.modulus = Schedule(100.0);
  m.area.modulus = Schedule(400.0);
  m.volume.modulus = Schedule(0.8);
  m.volume.reduced_volume = Schedule(reduced_volume);
  return m;
}

}  // namespace cortex::testing
