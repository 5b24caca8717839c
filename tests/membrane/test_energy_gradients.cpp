// Every membrane energy term's analytic gradient against central finite differences of
// its energy, on randomly perturbed spheres (closed) and planar patches (open).
#include <gtest/gtest.h>

#include <functional>
#include <memory>

#include "membrane/area_energy.hpp"
#include "membrane/bending_energy.hpp"
#include "membrane/regularization_energy.hpp"
#include "membrane/volume_energy.hpp"
#include "test_meshes.hpp"

namespace cortex {
namespace {

using TermFactory = std::function<std::unique_ptr<EnergyTerm>(Membrane&)>;

MembraneMechanics stressedMechanics(CurvatureEstimator estimator, AreaModel model) {
  MembraneMechanics m;
  m.bending_modulus = Schedule(100.0);
  m.spontaneous_curvature = Schedule(0.004);
  m.area_modulus = Schedule(400.0);
  m.tension = Schedule(0.02);
  m.volume_modulus = Schedule(0.8);
  m.regularization = Schedule(2.0);
  m.curvature = estimator;
  m.area_model = model;
  return m;
}

// Relative error ||g_fd - g|| / ||g|| of the analytic gradient of `term`.
double gradientError(Membrane& membrane, EnergyTerm& term, double h) {
  std::vector<double> x = testing::flatPositions(membrane.mesh());
  std::vector<double> g(x.size(), 0.0);
  std::uint64_t version = 1;
  term.evaluate({x.data(), g.data(), version++});
  double diff2 = 0.0, norm2 = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double x0 = x[i];
    x[i] = x0 + h;
    const double ep = term.evaluate({x.data(), nullptr, version++});
    x[i] = x0 - h;
    const double em = term.evaluate({x.data(), nullptr, version++});
    x[i] = x0;
    const double fd = (ep - em) / (2.0 * h);
    diff2 += (fd - g[i]) * (fd - g[i]);
    norm2 += g[i] * g[i];
  }
  EXPECT_GT(norm2, 0.0) << term.name() << " has a zero gradient: the test would be vacuous";
  return std::sqrt(diff2 / norm2);
}

struct Case {
  const char* label;
  TermFactory make;
  bool closed_only;
};

// Readable test parameters in ctest's listing.
void PrintTo(const Case& c, std::ostream* os) { *os << c.label; }

void setStressedTargets(Membrane& m) {
  // Targets away from the current state so that every term has a non-zero gradient.
  MembraneMechanics mech = m.mechanics();
  mech.target_area = Schedule(0.9 * m.material().initial_area);
  mech.target_volume = Schedule(0.8 * std::abs(m.material().initial_volume) + 1.0);
  m = Membrane(m.name(), m.mesh(), mech, m.fixedVertices());
}

class EnergyGradient : public ::testing::TestWithParam<std::tuple<Case, bool>> {};

TEST_P(EnergyGradient, MatchesCentralDifferences) {
  const auto& [c, closed] = GetParam();
  for (auto estimator : {CurvatureEstimator::kSigned, CurvatureEstimator::kUnsigned}) {
    SurfaceMesh mesh = closed ? testing::sphereMesh(250.0, 2, 6.0, Vec3(40, -30, 20))
                              : testing::patchMesh(300.0, 40.0, 5.0);
    Membrane membrane("m", mesh, stressedMechanics(estimator, AreaModel::kPerVertex), {});
    setStressedTargets(membrane);
    auto term = c.make(membrane);
    // Step 1e-4 nm on coordinates of O(100 nm): truncation ~h^2, round-off ~1e-16 E/h,
    // both far below the 1e-6 tolerance.
    const double err = gradientError(membrane, *term, 1e-4);
    EXPECT_LT(err, 1e-6) << c.label << (closed ? " on a sphere" : " on a patch")
                         << (estimator == CurvatureEstimator::kSigned ? " (signed)" : " (unsigned)");
  }
}

const Case kCases[] = {
    {"global area", [](Membrane& m) { return std::make_unique<GlobalAreaEnergy>(m); }, false},
    {"per-vertex area", [](Membrane& m) { return std::make_unique<PerVertexAreaEnergy>(m); }, false},
    {"tension", [](Membrane& m) { return std::make_unique<TensionEnergy>(m); }, false},
    {"volume", [](Membrane& m) { return std::make_unique<VolumeEnergy>(m); }, true},
    {"bending", [](Membrane& m) { return std::make_unique<BendingEnergy>(m); }, false},
    {"regularization", [](Membrane& m) { return std::make_unique<RegularizationEnergy>(m); }, false},
};

// Every term on a sphere; on an open patch every term but the volume, which only a
// closed membrane has.
std::vector<std::tuple<Case, bool>> allCases() {
  std::vector<std::tuple<Case, bool>> out;
  for (const Case& c : kCases) {
    out.emplace_back(c, true);
    if (!c.closed_only) out.emplace_back(c, false);
  }
  return out;
}

INSTANTIATE_TEST_SUITE_P(AllTerms, EnergyGradient, ::testing::ValuesIn(allCases()),
                         [](const auto& info) {
                           std::string s = std::get<0>(info.param).label;
                           for (char& ch : s)
                             if (ch == ' ' || ch == '-') ch = '_';
                           return s + (std::get<1>(info.param) ? "_sphere" : "_patch");
                         });

}  // namespace
}  // namespace cortex
