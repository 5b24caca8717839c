// The default membrane relaxation (membrane/shape_relaxation.hpp) against shapes and
// multipliers known independently: the SBL prolate and oblate branches, Laplace's law,
// the tension of a sphere with spontaneous curvature, and random smooth starting shapes
// nobody tuned it on.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <Eigen/Eigenvalues>

#include "core/constants.hpp"
#include "membrane/curvature.hpp"
#include "membrane/shape_relaxation.hpp"
#include "mesh/mesh_quality.hpp"
#include "sim/system.hpp"
#include "test_configs.hpp"
#include "test_meshes.hpp"

namespace cortex {
namespace {

using constants::kPi;

constexpr double kKappa = 100.0;  // pN nm
constexpr double kEightPiKappa = 8 * kPi * kKappa;

// Area and volume held exactly (the config's defaults without moduli), unsigned estimator
// (the default without spontaneous curvature), no numerical terms.
MembraneMechanics heldMechanics(double reduced_volume) {
  MembraneMechanics m;
  m.bending.modulus = Schedule(kKappa);
  m.bending.estimator = CurvatureEstimator::kUnsigned;
  m.area.model = AreaModel::kExact;
  m.volume.exact = true;
  m.volume.reduced_volume = Schedule(reduced_volume);
  return m;
}

MembraneConfig remeshed(MembraneConfig c, double mesh_size) {
  c.mesh_size = mesh_size;
  c.remesh = true;
  return c;
}

MembraneConfig spheroid(const Vec3& radii, double mesh_size, const MembraneMechanics& mechanics) {
  MembraneConfig c;
  c.name = "v";
  c.shape = "ellipsoid";
  c.radii = radii;
  c.mechanics = mechanics;
  return remeshed(c, mesh_size);
}

struct Relaxed {
  std::unique_ptr<System> system;
  ShapeRelaxationReport report;
  Membrane& membrane() { return *system->membranes()[0]; }
};

// tolerance 0: the default (the membrane's own force scale).
Relaxed relax(const MembraneConfig& c, double tolerance = 0.0) {
  Relaxed r{std::make_unique<System>(testing::configWith({c})), {}};
  ShapeRelaxationSettings s;
  s.force_tolerance = tolerance;
  r.report = relaxMembraneShape(r.membrane(), r.system->forceField(), 0.0, s);
  return r;
}

double bendingEnergy(Relaxed& r) {
  const Eigen::VectorXd x = r.system->coordinates();
  for (const TermEnergy& e : r.system->forceField().breakdown(x))
    if (e.name == "bending") return e.energy;
  return std::nan("");
}

// Principal axes of the surface (sorted), up to a common factor: the square roots of the
// eigenvalues of its second moment ∫(x − c)(x − c)ᵀ dA, vertex areas as weights (the
// adaptive mesh is finer where curved, so unweighted vertices would bias them).
Vec3 axes(Membrane& m) {
  const SurfaceMesh& mesh = m.mesh();
  const MeshGeometry g = m.currentGeometry();
  double area = 0.0;
  Vec3 c = Vec3::Zero();
  for (Index v = 0; v < mesh.numVertices(); ++v) c += g.vertex_area[v] * mesh.positions()[v], area += g.vertex_area[v];
  c /= area;
  Eigen::Matrix3d s = Eigen::Matrix3d::Zero();
  for (Index v = 0; v < mesh.numVertices(); ++v) {
    const Vec3 d = mesh.positions()[v] - c;
    s += g.vertex_area[v] * d * d.transpose();
  }
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(s).eigenvalues().cwiseSqrt();
}

// The roughness of the membrane's mean curvature (test_meshes.hpp).
double curvatureRoughness(Membrane& m) {
  return testing::curvatureRoughness(
      m.mesh(), vertexMeanCurvature(m.currentGeometry(), m.topology(), m.mechanics().bending.estimator));
}

// Every term's energy at the membrane's positions, from scratch.
double totalEnergy(Relaxed& r) {
  double total = 0.0;
  for (const TermEnergy& e : r.system->forceField().breakdown(r.system->coordinates())) total += e.energy;
  return total;
}

void expectHealthyEquilibrium(Relaxed& r, const std::string& what) {
  ASSERT_TRUE(r.report.converged) << what << ": " << r.report.stop_reason;
  // The report's energy is that of the shape it leaves: its final evaluation, which the
  // last outer step's may serve (normal_displacement_problem.hpp, EvaluationMemo), is of
  // these positions on this mesh, whatever remeshing happened in between. 1e-12: the
  // same sums, possibly in another order.
  EXPECT_NEAR(r.report.energy / totalEnergy(r), 1.0, 1e-12) << what;
  EXPECT_LT(r.report.max_normal_force, r.report.force_tolerance) << what;
  // The constraints are restored to 1e-10 relative after every step (kConstraintTolerance).
  EXPECT_LT(std::abs(r.report.area_error), 1e-8) << what;
  EXPECT_LT(std::abs(r.report.volume_error), 1e-8) << what;
  const MeshQuality q = measureQuality(r.membrane().mesh());
  EXPECT_GT(q.min_angle_deg, 20.0) << what;      // the remesher's floor is 25-30°
  EXPECT_GT(q.min_dihedral_cos, 0.5) << what;    // no fold, no crease
  EXPECT_LT(curvatureRoughness(r.membrane()), 0.10) << what;
  // Willmore: every closed surface has ∫H² dA ≥ 4π, so E_bend ≥ 8πκ.
  EXPECT_GT(bendingEnergy(r), 0.999 * kEightPiKappa) << what;
}

// Issue 10's failing case, smaller: a prolate spheroid of its own reduced volume 0.93
// relaxed at v = 0.9 ends on the prolate branch of Seifert, Berndl & Lipowsky (1991):
// E = 1.19 × 8πκ (their fig. 8; the converged discrete value is 1.190 at 10k vertices).
// Tolerance 1%: the discretization error of the bending energy at ~1.5k vertices.
// From an oblate start it stays on the oblate branch, a stationary shape 2.5% higher
// (SBL's oblate branch; in the continuum it is unstable to non-axisymmetric modes at
// v ≥ 0.8, so on finer meshes and tighter tolerances a relaxation may leave it for the
// prolate).
TEST(ShapeRelaxation, SpheroidsReachTheSblProlateAndOblateBranches) {
  Relaxed prolate = relax(spheroid(Vec3(812.26, 812.26, 1409.58), 100.0, heldMechanics(0.9)), 4e-3);
  expectHealthyEquilibrium(prolate, "prolate");
  const double e_prolate = bendingEnergy(prolate) / kEightPiKappa;
  EXPECT_NEAR(e_prolate, 1.19, 0.012);
  const Vec3 a = axes(prolate.membrane());
  EXPECT_NEAR(a[0] / a[1], 1.0, 0.02);  // axisymmetric
  EXPECT_GT(a[2] / a[1], 1.5);          // elongated

  Relaxed oblate = relax(spheroid(Vec3(1155.85, 1155.85, 696.12), 100.0, heldMechanics(0.9)), 4e-3);  // own v 0.93
  expectHealthyEquilibrium(oblate, "oblate");
  const double e_oblate = bendingEnergy(oblate) / kEightPiKappa;
  EXPECT_GT(e_oblate, e_prolate + 0.01);
  EXPECT_LT(e_oblate, 1.25);
  const Vec3 b = axes(oblate.membrane());
  EXPECT_NEAR(b[2] / b[1], 1.0, 0.02);
  EXPECT_LT(b[0] / b[1], 0.7);  // flattened
}

// A sphere deflated in one relaxation, on both meshers, reaches the prolate branch:
// 1.19 × 8πκ at v = 0.9 (SBL, as above), 1% for the discretization at 2.5k vertices.
// The icosphere, deflated along its own icosahedral pattern, kept the symmetry into a
// buckled stationary shape at 2.33 × 8πκ and exited converged; the relaxation now starts
// a near-sphere's deflation along an ellipsoidal mode (shape_relaxation.cpp). An
// irregular (marching-tetrahedra) sphere lands there too.
TEST(ShapeRelaxation, DeflatedSpheresOfEitherMesherReachTheProlateBranch) {
  for (const char* mesher : {"icosphere", "marching_tetrahedra"}) {
    MembraneConfig c;
    c.name = "v";
    c.shape = "sphere";
    c.mesher = mesher;
    c.radii = Vec3::Constant(500.0);
    c.mesh_size = 40.0;
    c.mechanics = heldMechanics(0.9);
    Relaxed r = relax(c);
    ASSERT_TRUE(r.report.converged) << mesher << ": " << r.report.stop_reason;
    EXPECT_NEAR(bendingEnergy(r) / kEightPiKappa, 1.19, 0.012) << mesher;
    const Vec3 a = axes(r.membrane());
    EXPECT_GT(a[2] / a[1], 1.5) << mesher;  // elongated
  }
}

// The same from a sphere whose volume a soft penalty holds (k_V = 1e-4 pN/nm², area held
// exactly, v = 0.6 asked): before the kick applied to penalties too, the sphere stayed
// at the sphere, a saddle (v = 0.9995, 1.598 × 8πκ, exit 0), while a slightly prolate
// start went to v = 0.862 at 1.521 × 8πκ. Both starts now end there (within 0.5%).
TEST(ShapeRelaxation, ASphereDeflatedByAVolumePenaltyLeavesTheSphere) {
  MembraneMechanics m;
  m.bending.modulus = Schedule(kKappa);
  m.bending.estimator = CurvatureEstimator::kUnsigned;
  m.area.model = AreaModel::kExact;
  m.volume.modulus = Schedule(1e-4);
  m.volume.reduced_volume = Schedule(0.6);
  std::vector<double> energies;
  for (const Vec3& radii : {Vec3(300.0, 300.0, 300.0), Vec3(320.0, 290.0, 290.0)}) {
    MembraneConfig c;
    c.name = "v";
    c.shape = radii[0] == radii[1] ? "sphere" : "ellipsoid";
    c.radii = radii;
    c.mesh_size = 25.0;
    c.mechanics = m;
    Relaxed r = relax(c);
    ASSERT_TRUE(r.report.converged) << r.report.stop_reason;
    energies.push_back(r.report.energy / kEightPiKappa);
  }
  EXPECT_NEAR(energies[0] / energies[1], 1.0, 0.005) << energies[0] << " against " << energies[1];
  EXPECT_LT(energies[0], 1.55);
}

// Laplace's law: a sphere under an imposed tension σ whose volume is held at a fraction
// of its own (its area free) shrinks, or inflates, to the sphere of that volume, and the
// pressure difference is the multiplier of the volume: Δp = 2σ/R (the bending energy of
// a sphere, 8πκ, does not depend on R). Inflating asks for more than the sphere of the
// initial area encloses: held all the same (the area is not held). Measured within 0.03%
// on a 2.5k-vertex icosphere; tolerance 0.3%.
TEST(ShapeRelaxation, PressureOfAHeldVolumeFollowsLaplacesLaw) {
  const double sigma = 0.01, r0 = 500.0;  // pN/nm, nm
  MembraneMechanics m;
  m.bending.modulus = Schedule(kKappa);
  m.bending.estimator = CurvatureEstimator::kUnsigned;
  m.area.model = AreaModel::kNone;
  m.tension.tension = Schedule(sigma);
  m.volume.exact = true;
  const SurfaceMesh mesh = testing::sphereMesh(r0, 4);
  for (const double fraction : {0.8, 1.2}) {
    SCOPED_TRACE(fraction);
    Relaxed r = relax(testing::membraneOf("v", mesh, [&] {
                        MembraneMechanics held = m;
                        const double v0 = 4.0 / 3.0 * kPi * r0 * r0 * r0;
                        held.volume.target_volume = Schedule(fraction * v0);
                        return held;
                      }()),
                      1e-4);
    ASSERT_TRUE(r.report.converged) << r.report.stop_reason;
    EXPECT_LT(std::abs(r.report.volume_error), 1e-8);
    const MeshGeometry g = r.membrane().currentGeometry();
    const double radius = std::cbrt(3.0 * g.volume / (4.0 * kPi));
    EXPECT_NEAR(r.membrane().equilibrium().pressure / (2.0 * sigma / radius), 1.0, 0.003);
    EXPECT_TRUE(std::isnan(r.membrane().equilibrium().tension));  // the area is not held
    const Vec3 a = axes(r.membrane());
    EXPECT_NEAR(a[0] / a[2], 1.0, 0.01);  // still a sphere
  }
}

// A sphere with spontaneous curvature H0 and its area held (volume free): stationary by
// symmetry; E = 8πκ (1 − R H0)² changes with R as a tension σ = −dE/dA balances, so the
// multiplier is σ = 2κ H0 (1 − R H0)/R. Measured within 0.1% on a 2.5k-vertex icosphere;
// tolerance 1% of the R H0 = 0.5 value. Also checks that R H0 = 0 gives no tension.
TEST(ShapeRelaxation, TensionOfAHeldAreaBalancesSpontaneousCurvature) {
  const double r0 = 500.0;
  for (double rh0 : {0.0, 0.5}) {
    MembraneMechanics m = heldMechanics(1.0);
    m.bending.estimator = CurvatureEstimator::kSigned;
    m.bending.spontaneous_curvature = Schedule(rh0 / r0);
    Relaxed r = relax(testing::membraneOf("v", testing::sphereMesh(r0, 4), m), 1e-4);
    ASSERT_TRUE(r.report.converged) << r.report.stop_reason;
    EXPECT_LT(std::abs(r.report.area_error), 1e-8);
    const double radius = std::sqrt(r.membrane().currentGeometry().area / (4.0 * kPi));
    const double h0 = rh0 / r0;
    const double expected = 2.0 * kKappa * h0 * (1.0 - radius * h0) / radius;
    const double scale = 2.0 * kKappa * 0.25 / (r0 * r0);  // the R H0 = 0.5 value
    EXPECT_NEAR(r.membrane().equilibrium().tension, expected, 0.01 * scale) << "R H0 = " << rh0;
  }
}

// A relaxed sphere remeshed finer (half the edge-length bounds: 1.8× the vertices, nearly
// half of them placed by the remesher) and relaxed again: no curvature hot spot. Right after the
// remesh, before relaxing, vertex placement errors of ~0.1 nm give |H − ring mean| of tens
// of percent (dH ~ 4δ/h²); the relaxation on the final mesh removes them. No valence rule
// is needed beyond the remesher's flips (docs/membrane.md).
TEST(ShapeRelaxation, RemeshedSphereRelaxesWithoutCurvatureHotSpots) {
  MembraneConfig c;
  c.name = "v";
  c.shape = "sphere";
  c.radii = Vec3::Constant(500.0);
  c.mechanics = heldMechanics(1.0);
  Relaxed r = relax(remeshed(c, 50.0), 1e-3);
  ASSERT_TRUE(r.report.converged) << r.report.stop_reason;
  const Index before = r.membrane().mesh().numVertices();
  RemeshSettings finer = *r.membrane().remeshing();
  finer.sizing.flat_size /= 2;
  finer.sizing.min_size /= 2;
  finer.sizing.max_size /= 2;
  r.membrane().setRemeshing(finer);
  r.membrane().remesh(finer);
  r.system->layOut();
  EXPECT_GT(r.membrane().mesh().numVertices(), 3 * before / 2);
  ShapeRelaxationSettings s;
  s.force_tolerance = 1e-3;
  const ShapeRelaxationReport again = relaxMembraneShape(r.membrane(), r.system->forceField(), 0.0, s);
  ASSERT_TRUE(again.converged) << again.stop_reason;
  EXPECT_LT(curvatureRoughness(r.membrane()), 0.10);
  EXPECT_NEAR(bendingEnergy(r) / kEightPiKappa, 1.0, 0.002);
}

// A smooth random vesicle: an ellipsoid of random semi-axes (0.6-1.4 × R) with low-mode
// noise, r = r_ellipsoid(u) exp(a f(u)) along the unit directions u of a sphere mesh, f a
// random polynomial of degree ≤ 4 in u (the span of the spherical harmonics l ≤ 4)
// normalized to unit variance; scaled to area 4π R².
struct RandomShape {
  SurfaceMesh mesh;
  double target_v;  // uniform in [0.6, 0.95]
};

RandomShape randomSmoothShape(std::uint64_t seed) {
  SurfaceMesh mesh = testing::sphereMesh(1.0, 4);
  std::mt19937_64 rng(seed);
  auto uniform = [&] { return (static_cast<double>(rng() >> 11) + 0.5) * 0x1.0p-53; };  // same on every platform
  auto normal = [&] { return std::sqrt(-2.0 * std::log(uniform())) * std::cos(2.0 * kPi * uniform()); };
  const Vec3 radii(0.6 + 0.8 * uniform(), 0.6 + 0.8 * uniform(), 0.6 + 0.8 * uniform());
  std::vector<std::array<int, 3>> powers;
  std::vector<double> coefficients;
  for (int i = 0; i <= 4; ++i)
    for (int j = 0; i + j <= 4; ++j)
      for (int k = 0; i + j + k <= 4; ++k)
        if (i + j + k >= 1) powers.push_back({i, j, k}), coefficients.push_back(normal() / (i + j + k));
  std::vector<double> f;
  for (const Vec3& p : mesh.positions()) {
    const Vec3 u = p.normalized();
    double s = 0.0;
    for (std::size_t t = 0; t < powers.size(); ++t)
      s += coefficients[t] * std::pow(u.x(), powers[t][0]) * std::pow(u.y(), powers[t][1]) * std::pow(u.z(), powers[t][2]);
    f.push_back(s);
  }
  double mean = 0.0, var = 0.0;
  for (double s : f) mean += s;
  mean /= static_cast<double>(f.size());
  for (double s : f) var += (s - mean) * (s - mean);
  const double sd = std::sqrt(var / static_cast<double>(f.size()));
  const double amplitude = 0.1 + 0.2 * uniform();
  for (Index v = 0; v < mesh.numVertices(); ++v) {
    const Vec3 u = mesh.positions()[v].normalized();
    const double r_ellipsoid = 1.0 / u.cwiseQuotient(radii).norm();
    mesh.positions()[v] = r_ellipsoid * std::exp(amplitude * (f[static_cast<std::size_t>(v)] - mean) / sd) * u;
  }
  MeshGeometry g;
  const std::vector<double> x = flatCoordinates(mesh.positions());
  g.compute(MeshTopology::of(mesh), x.data());
  const double scale = std::sqrt(4.0 * kPi * 1e6 / g.area);
  for (Vec3& p : mesh.positions()) p *= scale;
  return {mesh, 0.6 + 0.35 * uniform()};
}

double reducedVolume(const SurfaceMesh& mesh) {
  MeshGeometry g;
  const std::vector<double> x = flatCoordinates(mesh.positions());
  g.compute(MeshTopology::of(mesh), x.data());
  return 6.0 * std::sqrt(kPi) * g.volume / std::pow(g.area, 1.5);
}

// Twenty random smooth shapes, each relaxed to a random reduced volume in 0.6-0.95 (up
// to 0.3 from its own; the relaxation gets there by continuation): every one converges
// onto a healthy mesh (no fold, angles > 20°) with the constraints exact and no
// curvature hot spot, and is a minimum (relaxing it again changes nothing). Default
// tolerance: the membrane's own force scale.
TEST(ShapeRelaxation, RandomSmoothShapesRelaxOntoHealthyMeshes) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const RandomShape start = randomSmoothShape(seed);
    const std::string what = "seed " + std::to_string(seed) + ", v " + std::to_string(reducedVolume(start.mesh)) +
                             " -> " + std::to_string(start.target_v);
    Relaxed r = relax(remeshed(testing::membraneOf("v", start.mesh, heldMechanics(start.target_v)), 100.0));
    expectHealthyEquilibrium(r, what);
    const double e = bendingEnergy(r);
    const ShapeRelaxationSettings s;
    const ShapeRelaxationReport again = relaxMembraneShape(r.membrane(), r.system->forceField(), 0.0, s);
    ASSERT_TRUE(again.converged) << what;
    EXPECT_EQ(again.remeshes, 0) << what;
    // 5e-5: a second relaxation that takes steps along a soft mode relocates vertices
    // tangentially between outer steps, which moves the discrete energy by ~1e-5
    // (measured: ≤ 1e-7 for 19 of the 20 shapes, 9.5e-6 for one; 0.01 kBT).
    EXPECT_NEAR(bendingEnergy(r) / e, 1.0, 5e-5) << what;
  }
}

}  // namespace
}  // namespace cortex
