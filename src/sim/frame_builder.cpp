#include "sim/frame_builder.hpp"

#include "membrane/curvature.hpp"

namespace cortex {

Frame makeFrame(const System& system) {
  Frame frame;
  frame.time = system.time();
  frame.step = system.step;
  for (const auto& m : system.membranes()) {
    MembraneFrame mf;
    mf.name = m->name();
    for (const Vec3& p : m->mesh().positions()) mf.vertices.insert(mf.vertices.end(), {p.x(), p.y(), p.z()});
    for (const Tri& t : m->topology().triangles) mf.triangles.insert(mf.triangles.end(), t.begin(), t.end());
    mf.mean_curvature = vertexMeanCurvature(m->currentGeometry(), m->topology(), m->mechanics().curvature);
    frame.membranes.push_back(std::move(mf));
  }
  if (const ChemistryEngine* chem = system.chemistry()) {
    const CompartmentGrid& g = system.chemistryModel().grid;
    frame.grid_shape = {g.shape[0], g.shape[1], g.shape[2]};
    for (Index s = 0; s < static_cast<Index>(system.chemistryModel().species.size()); ++s) {
      SpeciesField field{system.chemistryModel().species[s].name, {}};
      field.copies.reserve(g.count());
      // C order over (x, y, z): z varies fastest, unlike the engine's x-fastest index.
      for (int i = 0; i < g.shape[0]; ++i)
        for (int j = 0; j < g.shape[1]; ++j)
          for (int k = 0; k < g.shape[2]; ++k) field.copies.push_back(chem->copies(g.index(i, j, k), s));
      frame.compartment_species.push_back(std::move(field));
    }
  }
  return frame;
}

}  // namespace cortex
