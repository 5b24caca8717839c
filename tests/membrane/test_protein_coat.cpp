// Curvature generation (issue 14; thesis eqs. 3.18–3.19): a protein coat covering an area
// fraction φ of the lipid changes the membrane's bending energy to
// 2 κ(φ) (H − H₀ − H_c φ)² per area, κ(φ) = ((1 − φ)/κ + φ/(κ + κ_p))⁻¹,
// H_c = H_p κ_p/(κ + κ_p). Gradients are in tests/test_energy_gradients.cpp.
//
// - A sphere coated evenly (copies ∝ vertex area, φ = 0.3 to 1e-3) has, relative to the
//   bare sphere, the closed-form ratio κ(φ)(1/R − H_c φ)² / (κ/R²), within 2e-3: the
//   estimator's error in H (~2e-4 on this icosphere) enters (H − H_c φ)² amplified by
//   H/(H − H_c φ) = 1.4, and φ is rounded to whole copies (1e-4).
// - The two-way coupling is one energy: the potential a sensing copy feels at a vertex
//   (sim/curvature_sensing.hpp, V_H = A_p ∂e/∂φ) equals the change of the coated
//   membrane's bending energy per copy added there, (E(n+1) − E(n−1))/2, to 1e-3
//   (the difference is second order in A_p/A_v = 0.01).
#include <gtest/gtest.h>

#include <cmath>

#include "core/constants.hpp"
#include "membrane/bending_energy.hpp"
#include "membrane/curvature.hpp"
#include "sim/curvature_sensing.hpp"
#include "test_meshes.hpp"

namespace cortex {
namespace {

constexpr double kKappa = 100.0, kKappaProtein = 150.0, kHp = 0.005;  // pN nm, pN nm, 1/nm
constexpr double kRadius = 300.0;                                       // nm

double energy(Membrane& m) {
  BendingEnergy term(m, m.mechanics().bending);
  const std::vector<double> x = flatCoordinates(m.mesh().positions());
  return term.evaluate({x.data(), nullptr, 1});
}

Membrane sphere() {
  MembraneMechanics mech;
  mech.bending = {Schedule(kKappa), Schedule(0.0), CurvatureEstimator::kSigned};
  return Membrane("vesicle", testing::sphereMesh(kRadius, 4), mech, {});
}

TEST(ProteinCoat, EvenCoatOnASphereScalesTheEnergyAsTheClosedForm) {
  Membrane m = sphere();
  const double bare = energy(m);
  const double phi = 0.3, copy_area = 0.05;  // nm^2 per copy: thousands of copies per vertex
  const MeshGeometry g = m.currentGeometry();
  std::vector<int> copies(static_cast<std::size_t>(m.mesh().numVertices()));
  for (Index v = 0; v < m.mesh().numVertices(); ++v) copies[v] = static_cast<int>(std::lround(phi * g.vertex_area[v] / copy_area));
  m.setSpecies({"coat"}, {copies});
  m.setCoat(ProteinCoat{0, copy_area, kKappaProtein, kHp});
  const double coated = energy(m);
  const double kappa_phi = 1.0 / ((1.0 - phi) / kKappa + phi / (kKappa + kKappaProtein));
  const double hc = kHp * kKappaProtein / (kKappa + kKappaProtein);
  const double expected = kappa_phi * std::pow(1.0 / kRadius - hc * phi, 2) / (kKappa / (kRadius * kRadius));
  EXPECT_NEAR(coated / bare, expected, 2e-3 * expected);
  EXPECT_LT(expected, 0.8) << "the coat should matter here";
}

TEST(ProteinCoat, SensingPotentialIsTheBendingEnergyPerCopyTheCoatAdds) {
  Membrane m = sphere();
  const MeshGeometry g = m.currentGeometry();
  const std::vector<double> H = vertexMeanCurvature(g, m.topology(), CurvatureEstimator::kSigned);
  const Index n = m.mesh().numVertices();
  std::vector<int> copies(static_cast<std::size_t>(n), 0);
  const double copy_area = 0.01 * g.vertex_area[0];
  const CurvatureSensingConfig protein{copy_area, kKappaProtein, kHp, true};
  m.setCoat(ProteinCoat{0, copy_area, kKappaProtein, kHp});
  for (Index v : {Index{0}, Index{17}, n / 2}) {
    for (int base : {1, 20}) {
      copies.assign(static_cast<std::size_t>(n), 0);
      const auto at = [&](int count) {
        copies[v] = count;
        m.setSpecies({"coat"}, {copies});
        return energy(m);
      };
      const double per_copy = (at(base + 1) - at(base - 1)) / 2.0;
      const double potential = curvatureSensingEnergy(protein, kKappa, 0.0, H[v], base, g.vertex_area[v]);
      EXPECT_NEAR(potential, per_copy, 1e-3 * std::abs(per_copy)) << "vertex " << v << ", " << base << " copies";
    }
  }
}

}  // namespace
}  // namespace cortex
