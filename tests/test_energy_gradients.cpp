// Every energy term's analytic gradient against central finite differences of its
// energy (tests/gradient_check.hpp): membrane terms on randomly perturbed spheres and
// patches with both curvature estimators and stressed targets, filament terms on random
// tangles, terms between membranes and filaments on straight filaments crossing over and
// under a rough sphere and patch; each after coordinates of another body, which it must
// not touch. A new term is one line in kCases.
#include <gtest/gtest.h>

#include <functional>
#include <memory>
#include <random>

#include "filament/boundary_energy.hpp"
#include "filament/branch_energy.hpp"
#include "filament/excluded_volume_energy.hpp"
#include "filament/filament_bending_energy.hpp"
#include "filament/spring_energy.hpp"
#include "filament/stretching_energy.hpp"
#include "filament/filament_networks.hpp"
#include "gradient_check.hpp"
#include "interact/membrane_bead_exclusion.hpp"
#include "membrane/area_energy.hpp"
#include "membrane/bending_energy.hpp"
#include "membrane/regularization_energy.hpp"
#include "membrane/volume_energy.hpp"
#include "test_meshes.hpp"

namespace cortex {
namespace {

// A term at some coordinates, with what it refers to kept alive.
struct Fixture {
  std::string where;
  std::shared_ptr<void> owner;
  std::unique_ptr<EnergyTerm> term;
  std::vector<double> x;
  std::size_t begin, end;  // the coordinates it may write
  double step;             // nm
};

struct Case {
  const char* label;
  std::function<std::vector<Fixture>()> fixtures;
};
void PrintTo(const Case& c, std::ostream* os) { *os << c.label; }

// --- membranes ---------------------------------------------------------------------------

constexpr Index kMembraneOffset = 5;  // points of another body before the membrane

// Parameters and targets away from the current state, so that every term has a non-zero
// gradient.
MembraneMechanics stressed(CurvatureEstimator estimator, const SurfaceMesh& mesh) {
  MembraneMechanics m;
  m.bending = {Schedule(100.0), Schedule(0.004), estimator};
  m.area = {AreaModel::kPerVertex, Schedule(400.0)};
  m.tension.tension = Schedule(0.02);
  m.regularization.strength = Schedule(2.0);
  const Membrane probe("probe", mesh, {}, {});
  m.target_area = Schedule(0.9 * probe.material().initial_area);
  if (mesh.isClosed()) {
    m.volume.modulus = Schedule(0.8);
    m.volume.target_volume = Schedule(0.8 * std::abs(probe.material().initial_volume) + 1.0);
  }
  return m;
}

using MembraneTermFactory = std::function<std::unique_ptr<EnergyTerm>(Membrane&)>;

// On a sphere and (unless closed_only) a patch, each with both curvature estimators.
std::function<std::vector<Fixture>()> onMembranes(MembraneTermFactory make, bool closed_only = false) {
  return [=] {
    std::vector<Fixture> out;
    for (bool closed : {true, false}) {
      if (!closed && closed_only) continue;
      for (auto estimator : {CurvatureEstimator::kSigned, CurvatureEstimator::kUnsigned}) {
        const SurfaceMesh mesh = closed ? testing::sphereMesh(250.0, 2, 6.0, Vec3(40, -30, 20))
                                        : testing::patchMesh(300.0, 40.0, 5.0);
        auto membrane = std::make_shared<Membrane>("m", mesh, stressed(estimator, mesh), std::vector<char>{});
        membrane->setOffset(kMembraneOffset);
        std::vector<double> x(3 * kMembraneOffset, 1.0);
        const std::vector<double> own = flatCoordinates(mesh.positions());
        x.insert(x.end(), own.begin(), own.end());
        // Step 1e-4 nm on coordinates of O(100 nm): truncation ~h^2, round-off ~1e-16 E/h,
        // both far below the 1e-6 tolerance.
        out.push_back({std::string(closed ? "sphere" : "patch") +
                           (estimator == CurvatureEstimator::kSigned ? ", signed" : ", unsigned"),
                       membrane, make(*membrane), std::move(x), 3 * kMembraneOffset, static_cast<std::size_t>(-1),
                       1e-4});
      }
    }
    return out;
  };
}

// --- filaments ---------------------------------------------------------------------------

using FilamentTermFactory =
    std::function<std::unique_ptr<EnergyTerm>(const FilamentLayout&, const std::vector<FilamentType>&)>;

// On three random tangles (filament_networks.hpp).
std::function<std::vector<Fixture>()> onFilaments(FilamentTermFactory make) {
  return [=] {
    std::vector<Fixture> out;
    for (unsigned seed = 1; seed <= 3; ++seed) {
      struct Owned {
        std::vector<FilamentType> types = filtest::testTypes();
        filtest::Network network;
      };
      auto owned = std::make_shared<Owned>();
      owned->network = filtest::randomNetwork(seed);
      auto term = make(owned->network.layout, owned->types);
      EXPECT_EQ(term->owner(), "filaments");
      out.push_back({"tangle " + std::to_string(seed), owned, std::move(term), owned->network.x,
                     3 * static_cast<std::size_t>(filtest::kOffset), static_cast<std::size_t>(-1), 1e-5});
    }
    return out;
  };
}

// --- membranes and filaments ---------------------------------------------------------------

using CouplingTermFactory = std::function<std::unique_ptr<EnergyTerm>(Membrane&, const FilamentNetwork&)>;

// A rough sphere and a rough patch, each with straight filaments of 3 cylinders whose
// beads lie 3-12 nm from the surface on either side (within the default cut-off of
// several triangles); the coordinates are [other body, membrane, filaments].
std::function<std::vector<Fixture>()> onMembraneAndFilaments(CouplingTermFactory make) {
  return [=] {
    std::vector<Fixture> out;
    for (bool closed : {true, false}) {
      struct Owned {
        std::unique_ptr<Membrane> membrane;
        std::unique_ptr<FilamentNetwork> network;
      };
      auto owned = std::make_shared<Owned>();
      const SurfaceMesh mesh = closed ? testing::sphereMesh(120.0, 2, 2.0) : testing::patchMesh(300.0, 40.0, 2.0);
      owned->membrane = std::make_unique<Membrane>("m", mesh, MembraneMechanics{}, std::vector<char>{});
      FilamentConfig config;
      config.types.resize(1);
      owned->network = std::make_unique<FilamentNetwork>(config);
      std::mt19937 rng(5);
      std::uniform_real_distribution<double> u(-1.0, 1.0);
      for (int f = 0; f < 6; ++f) {
        // Along the surface at a height of 3-12 nm, above or below.
        const double height = (f % 2 ? 1.0 : -1.0) * (7.5 + 4.5 * u(rng));
        Vec3 start, direction;
        if (closed) {
          const Vec3 radial = Vec3(u(rng), u(rng), u(rng)).normalized();
          start = (120.0 + height) * radial;
          direction = radial.cross(Vec3(u(rng), u(rng), u(rng))).normalized();
        } else {
          start = Vec3(80 * u(rng), 80 * u(rng), height);
          direction = Vec3(u(rng), u(rng), 0.05 * u(rng)).normalized();
        }
        owned->network->addFilament(makeStraightFilament(0, start, direction, 12, 4, 2.7));
      }
      owned->membrane->setOffset(kMembraneOffset);
      owned->network->setOffset(kMembraneOffset + owned->membrane->numPoints());
      std::vector<double> x(3 * kMembraneOffset, 1.0);
      const std::vector<double> own = flatCoordinates(mesh.positions());
      x.insert(x.end(), own.begin(), own.end());
      std::vector<double> beads(3 * owned->network->numPoints());
      owned->network->gather(beads.data());
      x.insert(x.end(), beads.begin(), beads.end());
      auto term = make(*owned->membrane, *owned->network);
      out.push_back({closed ? "sphere" : "patch", owned, std::move(term), std::move(x), 3 * kMembraneOffset,
                     static_cast<std::size_t>(-1), 1e-5});
    }
    return out;
  };
}

const Case kCases[] = {
    {"membrane_global_area", onMembranes([](Membrane& m) {
       return std::make_unique<GlobalAreaEnergy>(m, AreaParameters{AreaModel::kGlobal, Schedule(400.0)});
     })},
    {"membrane_per_vertex_area",
     onMembranes([](Membrane& m) { return std::make_unique<PerVertexAreaEnergy>(m, m.mechanics().area); })},
    {"membrane_tension",
     onMembranes([](Membrane& m) { return std::make_unique<TensionEnergy>(m, m.mechanics().tension); })},
    {"membrane_volume",
     onMembranes([](Membrane& m) { return std::make_unique<VolumeEnergy>(m, m.mechanics().volume); }, true)},
    {"membrane_bending",
     onMembranes([](Membrane& m) { return std::make_unique<BendingEnergy>(m, m.mechanics().bending); })},
    // A protein coat (curvature generation) of random copies, some vertices covered over.
    {"membrane_bending_coated", onMembranes([](Membrane& m) {
       std::mt19937 rng(9);
       std::vector<int> copies(static_cast<std::size_t>(m.mesh().numVertices()));
       for (int& n : copies) n = std::uniform_int_distribution<int>(0, 40)(rng);
       m.setSpecies({"coat"}, {copies});
       m.setCoat(ProteinCoat{0, 50.0, 150.0, 0.05});
       return std::make_unique<BendingEnergy>(m, m.mechanics().bending);
     })},
    {"membrane_regularization", onMembranes([](Membrane& m) {
       return std::make_unique<RegularizationEnergy>(m, m.mechanics().regularization);
     })},
    {"filament_stretching", onFilaments([](const FilamentLayout& l, const std::vector<FilamentType>& t) {
       return std::make_unique<FilamentStretchingEnergy>(l, t);
     })},
    {"filament_bending", onFilaments([](const FilamentLayout& l, const std::vector<FilamentType>& t) {
       return std::make_unique<FilamentBendingEnergy>(l, t);
     })},
    {"filament_excluded_volume", onFilaments([](const FilamentLayout& l, const std::vector<FilamentType>& t) {
       return std::make_unique<CylinderExclusionEnergy>(l, t);
     })},
    // Walls cutting through the tangle, so that beads sit on both sides.
    {"filament_boundary_box", onFilaments([](const FilamentLayout& l, const std::vector<FilamentType>&) {
       return std::make_unique<BoundaryRepulsionEnergy>(l, filtest::box(Vec3(5, 0, -2), Vec3(60, 55, 62)));
     })},
    {"filament_boundary_sphere", onFilaments([](const FilamentLayout& l, const std::vector<FilamentType>&) {
       return std::make_unique<BoundaryRepulsionEnergy>(l, filtest::sphere(Vec3(30, 30, 30), 45.0));
     })},
    {"filament_linkers", onFilaments([](const FilamentLayout& l, const std::vector<FilamentType>&) {
       return std::make_unique<SpringEnergy>(l, l.linkers, "linkers");
     })},
    {"filament_motors", onFilaments([](const FilamentLayout& l, const std::vector<FilamentType>&) {
       return std::make_unique<SpringEnergy>(l, l.motors, "motors");
     })},
    {"filament_branching", onFilaments([](const FilamentLayout& l, const std::vector<FilamentType>&) {
       return std::make_unique<BranchEnergy>(l);
     })},
    {"membrane_filament_exclusion", onMembraneAndFilaments([](Membrane& m, const FilamentNetwork& n) {
       return std::make_unique<MembraneBeadExclusion>(m, n, MembraneBeadExclusionParams{});
     })},
};

class EnergyGradient : public ::testing::TestWithParam<Case> {};

// Criterion: relative error < 1e-6 (measured 1e-10 ... 1e-8).
TEST_P(EnergyGradient, MatchesCentralDifferences) {
  double worst = 0.0;
  for (Fixture& f : GetParam().fixtures()) {
    const double err = testing::gradientError(*f.term, f.x, f.step, f.begin, f.end);
    EXPECT_LT(err, 1e-6) << GetParam().label << " on " << f.where;
    worst = std::max(worst, err);
  }
  std::printf("[ %s ] max relative gradient error %.2e\n", GetParam().label, worst);
}

INSTANTIATE_TEST_SUITE_P(AllTerms, EnergyGradient, ::testing::ValuesIn(kCases),
                         [](const auto& info) { return std::string(info.param.label); });

}  // namespace
}  // namespace cortex
