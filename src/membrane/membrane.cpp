#include "membrane/membrane.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "mesh/copy_carrier.hpp"
#include "mesh/lipid_flow.hpp"

namespace cortex {

double sphereVolumeOfArea(double area) {
  return std::pow(area, 1.5) / (6.0 * std::sqrt(constants::kPi));
}

Membrane::Membrane(std::string name, SurfaceMesh mesh, MembraneMechanics mechanics,
                   std::vector<char> fixed_vertices, const std::string& where)
    : name_(std::move(name)),
      mesh_(std::move(mesh)),
      topology_(MeshTopology::of(mesh_)),
      mechanics_(std::move(mechanics)),
      fixed_(std::move(fixed_vertices)) {
  if (!isClosed() && mechanics_.volume.isSet())
    throw InputError((where.empty() ? "membrane \"" + name_ + "\"" : where) +
                     ": the mesh is open (has a boundary), so volume_modulus, reduced_volume and "
                     "target_volume cannot apply");
  fixed_.resize(mesh_.numVertices(), 0);
  const MeshGeometry g = currentGeometry();
  material_.initial_area = g.area;
  material_.initial_volume = g.volume;
  material_.vertex_area0 = g.vertex_area;
  checkVolumeTarget(where);
}

// With the area held exactly, a target volume above the sphere's of that area is out of
// reach; the relaxation would hold the sphere instead and report it as a result. Checked
// at every knot of the two schedules (both are linear between knots, and the sphere's
// volume is convex in the area, so a violation between knots shows at one of them).
void Membrane::checkVolumeTarget(const std::string& where) const {
  const VolumeParameters& v = mechanics_.volume;
  if (mechanics_.area.model != AreaModel::kExact || !v.target_volume.isSet()) return;
  std::vector<double> times{0.0};
  for (const auto& [t, value] : v.target_volume.points()) times.push_back(t);
  for (const auto& [t, value] : mechanics_.target_area.points()) times.push_back(t);
  for (double t : times) {
    const double area = targetArea(t), sphere = sphereVolumeOfArea(area), target = targetVolume(t);
    if (target > sphere * (1.0 + 1e-9))
      throw InputError(fmt::format("{}: target_volume = {:g} nm^3 at t = {:g} s is more than a closed surface of its "
                                   "held area {:g} nm^2 can enclose (a sphere: {:g} nm^3; reduced volume {:.4g} > 1)",
                                   where.empty() ? "membrane \"" + name_ + "\"" : where, target, t, area, sphere,
                                   target / sphere));
  }
}

void Membrane::gather(double* x) const {
  for (const Vec3& p : mesh_.positions()) {
    x[0] = p.x(), x[1] = p.y(), x[2] = p.z();
    x += 3;
  }
}

void Membrane::scatter(const double* x) {
  for (Vec3& p : mesh_.positions()) {
    p = Vec3(x[0], x[1], x[2]);
    x += 3;
  }
}

void Membrane::frozen(char* mask) const { std::copy(fixed_.begin(), fixed_.end(), mask); }

double Membrane::targetVolume(double t) const {
  const VolumeParameters& v = mechanics_.volume;
  if (v.target_volume.isSet()) return v.target_volume.at(t);
  if (v.reduced_volume.isSet()) return v.reduced_volume.at(t) * sphereVolumeOfArea(targetArea(t));
  return material_.initial_volume;
}

MeshGeometry Membrane::currentGeometry() const {
  MeshGeometry g;
  g.compute(topology_, flatCoordinates(mesh_.positions()).data());
  return g;
}

double Membrane::coatCoverage() const {
  if (!coat_) return std::numeric_limits<double>::quiet_NaN();
  const std::vector<int>& copies = species_copies_[coat_->species];
  const MeshGeometry g = currentGeometry();
  double weighted = 0.0, total = 0.0;
  for (std::size_t v = 0; v < copies.size(); ++v) {
    if (copies[v] == 0) continue;
    weighted += copies[v] * coveredFraction(copies[v], coat_->area, g.vertex_area[v]);
    total += copies[v];
  }
  return total > 0 ? weighted / total : std::numeric_limits<double>::quiet_NaN();
}

RemeshStats Membrane::remesh(const RemeshSettings& settings) {
  // A flow under way first moves the copies for the deformation so far, on the
  // connectivity it was recorded on, and starts again on the new one.
  const bool flowing = !lipid_area_before_.empty();
  endLipidFlow();
  VertexPayload payload{&fixed_, speciesCountPointers(), {&material_.vertex_area0}};
  const RemeshStats stats = cortex::remesh(mesh_, payload, settings);
  relaxation_metric_ = {};  // built on the old connectivity
  // Rebuilt from its triangle list, the half-edge layout is the one a checkpoint restores
  // (edits leave it in edit order), so a resumed run remeshes exactly as this one.
  mesh_ = SurfaceMesh::fromSoup({mesh_.positions(), mesh_.triangles()}, name_);
  topology_ = MeshTopology::of(mesh_);
  cache_valid_ = false;
  ++connectivity_version_;
  remesh_totals_.splits += stats.splits;
  remesh_totals_.collapses += stats.collapses;
  remesh_totals_.flips += stats.flips;
  remesh_totals_.relocations += stats.relocations;
  remesh_totals_.sweeps += stats.sweeps;
  if (flowing) beginLipidFlow();
  return stats;
}

std::vector<std::vector<int>*> Membrane::speciesCountPointers() {
  std::vector<std::vector<int>*> counts;
  for (std::vector<int>& c : species_copies_) counts.push_back(&c);
  return counts;
}

void Membrane::beginLipidFlow() {
  lipid_area_before_ = anyCopies(speciesCountPointers()) ? dualCellAreas(mesh_) : std::vector<double>{};
}

void Membrane::endLipidFlow() {
  if (lipid_area_before_.empty()) return;
  const std::vector<std::vector<int>*> counts = speciesCountPointers();
  // Keyed by the state, like the remesher's carrier: a resumed run draws the same numbers.
  RandomStream random = streamKeyedByState(mesh_, counts);
  const LipidFlowStats stats =
      carryWithLipidFlow(mesh_, lipid_area_before_, dualCellAreas(mesh_), counts, random);
  if (stats.cells_drained > 0)
    spdlog::trace("membrane \"{}\": lipid flow out of {} cells (largest outflow {:.3g} of a cell)", name_,
                  stats.cells_drained, stats.largest_outflow);
  lipid_area_before_.clear();
}

void Membrane::setSpecies(std::vector<std::string> names, std::vector<std::vector<int>> copies) {
  if (names.size() != copies.size()) throw std::invalid_argument("membrane species: one copy array per name");
  for (const std::vector<int>& c : copies) {
    if (c.size() != static_cast<std::size_t>(mesh_.numVertices()))
      throw std::invalid_argument("membrane \"" + name_ + "\": species copies do not match the vertex count");
    for (int n : c)
      if (n < 0) throw std::invalid_argument("membrane \"" + name_ + "\": negative species copies");
  }
  species_names_ = std::move(names);
  species_copies_ = std::move(copies);
}

const MeshGeometry& Membrane::geometry(const Evaluation& e) {
  if (!cache_valid_ || cache_version_ != e.version) {
    cache_.compute(topology_, e.x + 3 * offset());
    cache_version_ = e.version;
    cache_valid_ = true;
  }
  return cache_;
}

}  // namespace cortex
