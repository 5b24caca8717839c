#include "sim/membrane_builder.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "core/constants.hpp"
#include "core/disjoint_sets.hpp"
#include "core/error.hpp"
#include "mesh/icosphere.hpp"
#include "mesh/implicit_shapes.hpp"
#include "mesh/marching_tetrahedra.hpp"
#include "mesh/mesh_file.hpp"
#include "mesh/planar_patch.hpp"

namespace cortex {

TriangleSoup initialMesh(const MembraneConfig& c) {
  if (c.shape == "sphere" && c.mesher == "icosphere")
    return icosphere(c.center, c.radii[0], icosphereSubdivisionsFor(c.radii[0], c.mesh_size));
  if (c.shape == "sphere") return meshImplicitSurface(implicitSphere(c.center, c.radii[0]), c.mesh_size);
  if (c.shape == "ellipsoid") return meshImplicitSurface(implicitEllipsoid(c.center, c.radii), c.mesh_size);
  if (c.shape == "plane") return planarPatch(c.center, c.size[0], c.size[1], c.mesh_size);
  return c.soup ? *c.soup : readMeshFile(c.file);
}

namespace {

double meanEdgeLength(const SurfaceMesh& m) {
  double sum = 0.0;
  for (Index h = 0; h < m.numHalfedges(); ++h) sum += (m.positions()[m.tip(h)] - m.positions()[m.tail(h)]).norm();
  return sum / m.numHalfedges();
}

// A loaded mesh has no mesh_size: its own mean edge length stands in for it.
RemeshSettings remeshSettings(const MembraneConfig& c, const SurfaceMesh& mesh, const std::string& where) {
  RemeshSettings r;
  SizingParameters& s = r.sizing;
  s.flat_size = c.mesh_size > 0 ? c.mesh_size : meanEdgeLength(mesh);
  s.min_size = c.min_size > 0 ? c.min_size : s.flat_size / 4.0;
  s.max_size = c.max_size > 0 ? c.max_size : 2.0 * s.flat_size;
  s.tolerance = c.remesh_tolerance > 0 ? c.remesh_tolerance : s.flat_size / 120.0;
  if (s.min_size > s.max_size)
    throw InputError(fmt::format("{}: min_size ({:g} nm) exceeds max_size ({:g} nm)", where, s.min_size, s.max_size));
  if (s.max_size < s.flat_size / 4.0)
    throw InputError(fmt::format("{}: max_size ({:g} nm) is under a quarter of the mesh size ({:g} nm): remeshing "
                                 "would multiply the vertices more than sixteen-fold",
                                 where, s.max_size, s.flat_size));
  return r;
}

// A loaded mesh's coordinates are nanometres, bounded like generated shapes' (beyond a
// metre they keep too few digits for a mesh of nanometres), and edges under 0.1 nm are
// most likely a file in µm or m (a 1 µm vesicle in µm has edges of ~0.05): both ran to
// exit 0 with nonsense.
void checkLoadedScale(const SurfaceMesh& mesh, const std::string& where) {
  for (const Vec3& x : mesh.positions())
    if (!(x.cwiseAbs().maxCoeff() <= constants::kMaxCoordinate))
      throw InputError(fmt::format("{}: a vertex at ({:g}, {:g}, {:g}) nm lies beyond {:g} nm (a metre) of the origin",
                                   where, x[0], x[1], x[2], constants::kMaxCoordinate));
  const double edge = meanEdgeLength(mesh);
  if (!(edge >= 0.1))
    throw InputError(fmt::format("{}: its mean edge is {:.3g} nm; coordinates are read in nm (is the file in µm?)",
                                 where, edge));
}

// A membrane is one surface: a file holding two (two vesicles, a vesicle and a stray
// triangle) was taken as one membrane with one area and one volume, and ran to exit 0
// with the pair's reduced volume.
void checkConnected(const SurfaceMesh& mesh, const std::string& where) {
  DisjointSets pieces_of(mesh.numVertices());
  for (const Tri& t : mesh.triangles())
    for (int k = 1; k < 3; ++k) pieces_of.join(t[0], t[k]);
  Index pieces = 0, stray = -1;
  for (Index v = 0; v < mesh.numVertices(); ++v) {
    if (pieces_of.root(v) == v) ++pieces;
    if (stray < 0 && pieces_of.root(v) != pieces_of.root(0)) stray = v;
  }
  if (pieces > 1)
    throw InputError(fmt::format("{}: the mesh is {} separate pieces (vertex {} is not connected to vertex 0); a "
                                 "membrane is one connected surface: give each piece its own [[membrane]]",
                                 where, pieces, stray));
}

// The generated shape's mesh; a mesh_size too coarse for the shape is named as the key it
// is (the message named the mesher's function, meshImplicitSurface).
TriangleSoup generatedMesh(const MembraneConfig& c, const std::string& where) {
  try {
    return initialMesh(c);
  } catch (const InputError& e) {
    if (c.shape != "sphere" && c.shape != "ellipsoid") throw;
    throw InputError(fmt::format("{}: mesh_size = {:g} nm is too coarse to mesh a shape whose smallest radius is {:g} "
                                 "nm ({}); keep it under about 0.7 x that radius{}",
                                 where, c.mesh_size, c.radii.minCoeff(), e.what(),
                                 c.shape == "sphere" ? " (or use mesher = \"icosphere\")" : ""));
  }
}

// A generated shape meshed with edges over kCoarseEdge of its smallest radius: the run is
// valid, but its bending energy carries a discretization error of percents (0.3 R: 1.3%
// on an icosphere, about 0.14 (edge/R)², docs/membrane.md; a 14-vertex "sphere" from
// mesh_size = 0.72 R was 20% off), which the log should say beside the numbers.
constexpr double kCoarseEdge = 0.3;

void warnIfCoarse(const SurfaceMesh& mesh, const MembraneConfig& c, const std::string& where) {
  const double radius = c.radii.minCoeff(), ratio = meanEdgeLength(mesh) / radius;
  if (!(ratio > kCoarseEdge)) return;
  spdlog::warn("{}: mesh_size = {:g} nm gives {} vertices with a mean edge of {:.2g} x its smallest radius ({:g} nm): "
               "the bending energy is then off by percents (at least about {:.0f}% on a sphere, docs/membrane.md, "
               "Convergence); a mesh_size under a tenth of the radius keeps it under 0.5%",
               where, c.mesh_size, mesh.numVertices(), ratio, radius, 100.0 * 0.14 * ratio * ratio);
}

void reverseOrientation(TriangleSoup& soup) {
  for (Tri& t : soup.triangles) std::swap(t[1], t[2]);
}

}  // namespace

std::unique_ptr<Membrane> buildMembrane(const MembraneConfig& c, const std::string& source,
                                        const MembraneState* restored) {
  const std::string where = fmt::format("{}: membrane \"{}\"", source, c.name);
  TriangleSoup soup = restored ? restored->mesh : generatedMesh(c, where);
  const std::string mesh_source = c.shape == "mesh" && !restored ? c.file.string() : where;
  SurfaceMesh mesh = SurfaceMesh::fromSoup(soup, mesh_source);
  if (c.shape == "mesh" && !restored) {
    checkLoadedScale(mesh, where + ", file " + c.file.string());
    checkConnected(mesh, where + ", file " + c.file.string());
  }

  std::vector<char> fixed;
  if (restored) {
    fixed = restored->fixed;
  } else {
    fixed.resize(mesh.numVertices(), 0);
    for (Index v = 0; v < mesh.numVertices(); ++v) fixed[v] = mesh.isBoundaryVertex(v) ? 1 : 0;
  }
  // A loaded mesh that is open gets a patch's default area model (io/config.cpp): free.
  MembraneMechanics mechanics = c.mechanics;
  if (c.shape == "mesh" && !c.area_model_given && !mesh.isClosed() && mechanics.area.model == AreaModel::kExact) {
    mechanics.area.model = AreaModel::kNone;
    spdlog::info("{}: the mesh is open: its area is free (area_model = \"none\", the default for patches)", where);
  }
  auto membrane = std::make_unique<Membrane>(c.name, std::move(mesh), mechanics, fixed, where);

  if (!restored && membrane->isClosed() && membrane->material().initial_volume < 0.0) {
    // A closed mesh whose triangles face inwards: flip it rather than simulate inside-out.
    spdlog::warn("{}: mesh triangles are oriented inwards; reversing them", where);
    reverseOrientation(soup);
    membrane = std::make_unique<Membrane>(c.name, SurfaceMesh::fromSoup(soup, mesh_source), c.mechanics, fixed, where);
  }
  if (!restored && (c.shape == "sphere" || c.shape == "ellipsoid")) warnIfCoarse(membrane->mesh(), c, where);
  if (restored) {
    membrane->setMaterial(restored->material);
    membrane->setRemeshTotals(restored->remesh_totals);
    membrane->setEquilibrium(restored->equilibrium);
    membrane->relaxationMetric() = restored->metric;
    std::vector<std::string> names;
    for (const SurfaceSpeciesConfig& sp : c.species) names.push_back(sp.name);
    if (restored->species != names)
      throw InputError(fmt::format("checkpoint: membrane \"{}\" has other species than the config's [[membrane.species]]",
                                   c.name));
    try {
      membrane->setSpecies(names, restored->species_copies);
    } catch (const std::invalid_argument& e) {
      throw InputError(fmt::format("checkpoint is damaged: {}", e.what()));
    }
  }
  for (std::size_t j = 0; j < c.species.size(); ++j)
    if (const auto& k = c.species[j].curvature; k && k->generates)
      membrane->setCoat(ProteinCoat{static_cast<Index>(j), k->area, k->bending_modulus, k->spontaneous_curvature});
  if (c.remesh)
    membrane->setRemeshing(restored && restored->remeshing ? *restored->remeshing
                                                           : remeshSettings(c, membrane->mesh(), where));
  return membrane;
}

MembraneState membraneState(const Membrane& m) {
  MembraneState s;
  s.mesh = {m.mesh().positions(), m.topology().triangles};
  s.fixed = m.fixedVertices();
  s.material = m.material();
  s.remesh_totals = m.remeshTotals();
  s.remeshing = m.remeshing();
  s.equilibrium = m.equilibrium();
  s.metric = m.relaxationMetric();
  s.species = m.speciesNames();
  s.species_copies = m.speciesCopies();
  return s;
}

const Membrane& closedMembrane(const std::vector<std::unique_ptr<Membrane>>& membranes, const std::string& name,
                               const std::string& key) {
  for (const auto& m : membranes) {
    if (m->name() != name) continue;
    if (!m->isClosed()) throw InputError(fmt::format("{}: membrane \"{}\" is open and encloses nothing", key, name));
    return *m;
  }
  throw InputError(fmt::format("{}: no membrane is named \"{}\"", key, name));
}

}  // namespace cortex
