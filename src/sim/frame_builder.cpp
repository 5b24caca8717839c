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
  return frame;
}

}  // namespace cortex
