#include "membrane/membrane.hpp"

#include <cmath>

#include "core/constants.hpp"

namespace cortex {

double sphereVolumeOfArea(double area) {
  return std::pow(area, 1.5) / (6.0 * std::sqrt(constants::kPi));
}

namespace {
std::vector<double> flatten(const std::vector<Vec3>& p) {
  std::vector<double> x(3 * p.size());
  for (std::size_t i = 0; i < p.size(); ++i)
    for (int k = 0; k < 3; ++k) x[3 * i + k] = p[i][k];
  return x;
}
}  // namespace

Membrane::Membrane(std::string name, SurfaceMesh mesh, MembraneMechanics mechanics,
                   std::vector<char> fixed_vertices)
    : name_(std::move(name)),
      mesh_(std::move(mesh)),
      topology_(MeshTopology::of(mesh_)),
      mechanics_(std::move(mechanics)),
      fixed_(std::move(fixed_vertices)) {
  fixed_.resize(mesh_.numVertices(), 0);
  const MeshGeometry g = currentGeometry();
  material_.initial_area = g.area;
  material_.initial_volume = g.volume;
  material_.vertex_area0 = g.vertex_area;
  setTime(0.0);
}

MeshGeometry Membrane::currentGeometry() const {
  MeshGeometry g;
  g.compute(topology_, flatten(mesh_.positions()).data());
  return g;
}

void Membrane::setTime(double t) {
  const MembraneMechanics& m = mechanics_;
  now_.kappa = m.bending_modulus.at(t);
  now_.h0 = m.spontaneous_curvature.at(t);
  now_.k_area = m.area_modulus.at(t);
  now_.gamma = m.tension.at(t);
  now_.k_volume = m.volume_modulus.at(t);
  now_.k_regularization = m.regularization.at(t);
  now_.area0 = m.target_area.isSet() ? m.target_area.at(t) : material_.initial_area;
  vertex_area0_scale_ = now_.area0 / material_.initial_area;
  if (m.target_volume.isSet())
    now_.volume0 = m.target_volume.at(t);
  else if (m.reduced_volume.isSet())
    now_.volume0 = m.reduced_volume.at(t) * sphereVolumeOfArea(now_.area0);
  else
    now_.volume0 = material_.initial_volume;
}

RemeshStats Membrane::remesh(const RemeshSettings& settings) {
  VertexPayload payload{&fixed_, {}, {&material_.vertex_area0}};
  const RemeshStats stats = cortex::remesh(mesh_, payload, settings);
  // Rebuilt from its triangle list, the half-edge layout is the one a checkpoint restores
  // (edits leave it in edit order), so a resumed run remeshes exactly as this one.
  mesh_ = SurfaceMesh::fromSoup({mesh_.positions(), mesh_.triangles()}, name_);
  topology_ = MeshTopology::of(mesh_);
  cache_valid_ = false;
  remesh_totals_.splits += stats.splits;
  remesh_totals_.collapses += stats.collapses;
  remesh_totals_.flips += stats.flips;
  remesh_totals_.relocations += stats.relocations;
  remesh_totals_.sweeps += stats.sweeps;
  return stats;
}

const MeshGeometry& Membrane::geometry(const Evaluation& e) {
  if (!cache_valid_ || cache_version_ != e.version) {
    cache_.compute(topology_, e.x + 3 * dof_offset_);
    cache_version_ = e.version;
    cache_valid_ = true;
  }
  return cache_;
}

}  // namespace cortex
