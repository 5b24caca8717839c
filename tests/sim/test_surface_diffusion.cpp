// Surface species diffusing between the dual cells of a mesh (issue 14, first part:
// thesis eqs. 3.8–3.11 without a potential), through the chemistry engines: the mean
// squared displacement on a flat random Delaunay mesh is 4Dt, the mean cosine of the
// angle travelled on a sphere of radius R is e^{−2Dt/R²} (both within 2%, the issue's
// tolerance), rates are D (cot α + cot β)/(2|C_i|) ≥ 0 with |C_i| one third of the
// one-ring area, and edges that are not locally Delaunay are clipped both ways.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "chem/chemistry_engine.hpp"
#include "mesh/cotan.hpp"
#include "sim/surface_graph.hpp"
#include "test_meshes.hpp"

namespace cortex {
namespace {

// Flips every interior edge whose opposite angles sum to more than π until none is left
// (Lawson's algorithm: a flat mesh ends Delaunay).
void makeDelaunay(SurfaceMesh& mesh) {
  for (bool flipped = true; flipped;) {
    flipped = false;
    for (Index h = 0; h < mesh.numHalfedges(); ++h) {
      if (mesh.isBoundaryHalfedge(h) || mesh.isBoundaryHalfedge(mesh.twin(h))) continue;
      if (cotanOpposite(mesh, h) + cotanOpposite(mesh, mesh.twin(h)) < -1e-12 && mesh.flip(h)) flipped = true;
    }
  }
}

// A 2 µm square patch of ~11,000 vertices, those two or more edges from its border
// moved at random in the plane by up to 0.35 edge lengths, then made Delaunay (boundary
// edges cannot be flipped: moving their neighbours could leave them with a negative
// cotangent sum).
SurfaceMesh randomFlatMesh(unsigned seed) {
  SurfaceMesh mesh = testing::patchMesh(2000.0, 20.0);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-7.0, 7.0);
  for (Vec3& x : mesh.positions())
    if (std::max(std::abs(x.x()), std::abs(x.y())) < 1000.0 - 30.0) x += Vec3(u(rng), u(rng), 0.0);
  makeDelaunay(mesh);
  return mesh;
}

// A sphere of radius R, its vertices moved at random along it by up to 0.3 edge lengths
// and put back on it, then flipped towards Delaunay (an irregular mesh of a true sphere).
SurfaceMesh randomSphereMesh(double radius, unsigned seed) {
  SurfaceMesh mesh = testing::sphereMesh(radius, 4);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-0.3 * 0.08 * radius, 0.3 * 0.08 * radius);
  for (Vec3& x : mesh.positions()) x = radius * (x + Vec3(u(rng), u(rng), u(rng))).normalized();
  makeDelaunay(mesh);
  return mesh;
}

// Copies per vertex after `copies` are released at vertex `start` and diffuse for each
// of `times` in turn (one engine, one 3D compartment holding the whole surface). The
// next-subvolume engine: the direct method's O(subvolumes) cost per event makes these
// 10⁷-event runs take minutes (both engines agree on graphs in test_subvolume_graph).
std::vector<std::vector<int>> diffuse(const SurfaceMesh& mesh, double diffusion, int copies, Index start,
                                      const std::vector<double>& times, EngineKind kind) {
  ChemistryModel model;
  model.volumes.size = {1e12};
  model.volumes.start = {0, 0};
  model.surfaces = {"membrane"};
  model.species = {{"P", diffusion, 0}};
  auto engine = makeChemistryEngine(kind, model, {0}, 17);
  const DualCellGraph cells = dualCellGraph(mesh);
  std::vector<int> initial(static_cast<std::size_t>(mesh.numVertices()), 0);
  initial[start] = copies;
  engine->setSurface(0, cells.graph, std::vector<Index>(initial.size(), 0), initial);
  std::vector<std::vector<int>> out;
  for (double t : times) {
    engine->advance(t);
    std::vector<int> now(initial.size());
    for (std::size_t j = 0; j < now.size(); ++j) now[j] = engine->copies(engine->regionStart(1) + static_cast<Index>(j), 0);
    out.push_back(std::move(now));
  }
  return out;
}

Index nearestVertex(const SurfaceMesh& mesh, const Vec3& p) {
  Index best = 0;
  for (Index v = 1; v < mesh.numVertices(); ++v)
    if ((mesh.positions()[v] - p).squaredNorm() < (mesh.positions()[best] - p).squaredNorm()) best = v;
  return best;
}

TEST(DualCellGraph, CellsTileTheSurfaceAndRatesFollowTheCotangentFormula) {
  const SurfaceMesh mesh = randomFlatMesh(3);
  const DualCellGraph cells = dualCellGraph(mesh);
  EXPECT_NO_THROW(validate(cells.graph, "dual cells"));  // reverse edges, detailed balance
  double area = 0.0;
  for (double a : cells.graph.size) area += a;
  EXPECT_NEAR(area, 2000.0 * 2000.0, 1e-6 * 4e6);
  EXPECT_EQ(cells.clipped_edges, 0);  // Delaunay: no cotangent sum < 0
  // One interior vertex by hand: rate to each neighbour D (cot α + cot β)/(2|C|) ≥ 0.
  const Index v = nearestVertex(mesh, Vec3(0, 0, 0));
  double one_ring = 0.0;
  for (Index h : mesh.outgoingHalfedges(v)) {
    const Vec3 &a = mesh.positions()[v], &b = mesh.positions()[mesh.tip(h)],
               &c = mesh.positions()[mesh.tip(mesh.next(h))];
    one_ring += (b - a).cross(c - a).norm() / 2;
  }
  EXPECT_NEAR(cells.graph.size[v], one_ring / 3, 1e-9 * one_ring);
  for (Index e = cells.graph.start[v]; e < cells.graph.start[v + 1]; ++e) {
    const Index j = cells.graph.target[e];
    Index h = kNone;
    for (Index k : mesh.outgoingHalfedges(v))
      if (mesh.tip(k) == j) h = k;
    ASSERT_NE(h, kNone);
    // The angles opposite edge vj, from their triangles' corners.
    const auto angle = [&](Index corner_half_edge) {
      const Index p = mesh.tip(mesh.next(corner_half_edge));
      const Vec3 a = mesh.positions()[mesh.tail(corner_half_edge)] - mesh.positions()[p],
                 b = mesh.positions()[mesh.tip(corner_half_edge)] - mesh.positions()[p];
      return std::atan2(a.cross(b).norm(), a.dot(b));
    };
    const double rate = 1.0 / cells.graph.hop_length2[e];  // per unit D
    const double expected = (1 / std::tan(angle(h)) + 1 / std::tan(angle(mesh.twin(h)))) / (2 * cells.graph.size[v]);
    EXPECT_NEAR(rate, expected, 1e-9 * expected);
    EXPECT_GT(rate, 0.0);
  }
}

TEST(DualCellGraph, AnEdgeThatIsNotDelaunayIsClippedBothWays) {
  // Two triangles sharing a long edge whose opposite angles are both obtuse.
  const TriangleSoup soup{{Vec3(-10, 0, 0), Vec3(10, 0, 0), Vec3(0, 2, 0), Vec3(0, -2, 0)}, {{0, 1, 2}, {1, 0, 3}}};
  const DualCellGraph cells = dualCellGraph(SurfaceMesh::fromSoup(soup, "kite"));
  EXPECT_EQ(cells.clipped_edges, 1);
  for (Index e = cells.graph.start[0]; e < cells.graph.start[1]; ++e) EXPECT_NE(cells.graph.target[e], 1);
  for (Index e = cells.graph.start[1]; e < cells.graph.start[2]; ++e) EXPECT_NE(cells.graph.target[e], 0);
  EXPECT_NO_THROW(validate(cells.graph, "kite"));
}

TEST(SurfaceDiffusion, MeanSquaredDisplacementIsFourDtOnARandomFlatMesh) {
  // 40,000 copies from the vertex nearest the centre, D = 1 µm²/s, until the cloud's rms
  // radius is 300 and 424 nm (far from the edges 1 µm away): MSD = 4Dt within 2%. The
  // statistical error of the mean of r² over N copies is ~1/√N = 0.5%; the walk's MSD
  // rate differs from 4D at single vertices but averages to it over the cloud.
  const SurfaceMesh mesh = randomFlatMesh(5);
  const double d = 1e6, t1 = 0.0225, t2 = 0.045;
  const Index start = nearestVertex(mesh, Vec3(0, 0, 0));
  const auto states = diffuse(mesh, d, 40000, start, {t1, t2}, EngineKind::kNextSubvolume);
  for (std::size_t k = 0; k < 2; ++k) {
    double msd = 0.0, mean_x = 0.0;
    long total = 0;
    for (Index v = 0; v < mesh.numVertices(); ++v) {
      const Vec3 r = mesh.positions()[v] - mesh.positions()[start];
      msd += states[k][v] * r.squaredNorm();
      mean_x += states[k][v] * r.x();
      total += states[k][v];
    }
    ASSERT_EQ(total, 40000);  // conserved
    msd /= total, mean_x /= total;
    const double t = k ? t2 : t1;
    std::printf("[ measured ] t = %.4f s: MSD %.0f nm² against 4Dt = %.0f (%+.2f%%), mean x %.2f nm\n", t, msd,
                4 * d * t, 100 * (msd / (4 * d * t) - 1), mean_x);
    EXPECT_NEAR(msd, 4 * d * t, 0.02 * 4 * d * t);
    EXPECT_LT(std::abs(mean_x), 0.02 * std::sqrt(4 * d * t));  // no drift
  }
}

TEST(SurfaceDiffusion, MeanCosineOnASphereDecaysAsExpMinus2DtOverRSquared) {
  // 50,000 copies from a vertex of an irregular mesh of a sphere of radius 1 µm, D = 1
  // µm²/s: ⟨cos θ⟩ = e^{−2Dt/R²} at 2Dt/R² = 0.5 and 1, within 2% (standard error of the
  // mean ~0.4%, discretization O(h²/R²) with h ≈ 0.08 R).
  const double r = 1000.0, d = 1e6;
  const SurfaceMesh mesh = randomSphereMesh(r, 7);
  const Index start = nearestVertex(mesh, Vec3(0, 0, r));
  const Vec3 pole = mesh.positions()[start].normalized();
  const double t1 = 0.25, t2 = 0.5;
  const auto states = diffuse(mesh, d, 50000, start, {t1, t2}, EngineKind::kNextSubvolume);
  for (std::size_t k = 0; k < 2; ++k) {
    double mean_cos = 0.0;
    for (Index v = 0; v < mesh.numVertices(); ++v) mean_cos += states[k][v] * mesh.positions()[v].normalized().dot(pole);
    mean_cos /= 50000.0;
    const double t = k ? t2 : t1, expected = std::exp(-2 * d * t / (r * r));
    std::printf("[ measured ] 2Dt/R² = %.2f: <cos θ> %.4f against %.4f (%+.2f%%)\n", 2 * d * t / (r * r), mean_cos,
                expected, 100 * (mean_cos / expected - 1));
    EXPECT_NEAR(mean_cos, expected, 0.02 * expected);
  }
}

}  // namespace
}  // namespace cortex
