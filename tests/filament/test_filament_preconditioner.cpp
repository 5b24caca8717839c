// The filament network's Hessian model (filament_preconditioner.hpp): exact where it
// claims to be, and a preconditioner that changes the speed of a relaxation, never its
// minimum.
#include <gtest/gtest.h>

#include <memory>
#include <random>

#include "filament/branch_energy.hpp"
#include "filament/filament_bending_energy.hpp"
#include "filament/filament_preconditioner.hpp"
#include "filament/spring_energy.hpp"
#include "filament/stretching_energy.hpp"
#include "filament_networks.hpp"
#include "mech/force_field.hpp"
#include "mech/minimizer.hpp"

namespace cortex {
namespace {

using namespace filtest;

// The internal terms of a layout (no contacts), over a vector with kOffset dummy beads
// first, which stay frozen.
ForceField internalTerms(const FilamentLayout& layout, const std::vector<FilamentType>& types) {
  ForceField f;
  f.add(std::make_unique<FilamentStretchingEnergy>(layout, types));
  f.add(std::make_unique<FilamentBendingEnergy>(layout, types));
  f.add(std::make_unique<SpringEnergy>(layout, layout.linkers, "linkers"));
  f.add(std::make_unique<SpringEnergy>(layout, layout.motors, "motors"));
  f.add(std::make_unique<BranchEnergy>(layout));
  std::vector<char> frozen(3 * static_cast<std::size_t>(kOffset + layout.num_beads), 0);
  std::fill(frozen.begin(), frozen.begin() + 3 * kOffset, 1);
  f.setFrozen(std::move(frozen));
  return f;
}

// Along a straight filament at rest the Gauss-Newton parts are the whole Hessian: the
// model less its shift must equal the finite-difference Hessian of stretching and bending.
// Central differences of the exact gradient with h = 1e-4 nm err by ~h^2 * (third
// derivative) ~ 1e-8 of the largest entry (k_s); the bound 1e-6 of it leaves room for
// rounding in the 1e-4 nm difference (gradients of ~1e-2 pN read to ~1e-14 relative).
TEST(FilamentPreconditioner, IsTheExactHessianOfAStraightFilamentAtRest) {
  const std::vector<FilamentType> types = testTypes();
  std::mt19937 rng(5);
  std::normal_distribution<double> gauss(0.0, 1.0);
  for (const Index type : {0, 1}) {
    const Vec3 axis = Vec3(gauss(rng), gauss(rng), gauss(rng)).normalized();
    const std::vector<double> lengths = {20.0, 8.0, 27.0, 2.7, 15.0};
    FilamentLayout layout;
    layout.bead_offset = kOffset;
    layout.num_beads = static_cast<Index>(lengths.size()) + 1;
    layout.version = 1;
    Eigen::VectorXd x = Eigen::VectorXd::Zero(3 * (kOffset + layout.num_beads));
    Vec3 p(3.0, -4.0, 7.0);
    for (Index b = 0; b < layout.num_beads; ++b) {
      x.segment<3>(3 * (kOffset + b)) = p;
      if (b + 1 < layout.num_beads) {
        layout.cylinders.push_back({b, b + 1, 0, type, lengths[b]});
        p += lengths[b] * axis;
      }
      if (b >= 1 && b + 1 < layout.num_beads) layout.hinges.push_back({b - 1, b, b + 1, type});
    }
    ForceField f = internalTerms(layout, types);
    FilamentPreconditioner model;
    ASSERT_TRUE(model.build(layout, types, x, std::vector<char>(layout.num_beads, 0)));
    const Index n = 3 * layout.num_beads;
    const double shift = FilamentPreconditioner::kShiftFraction * types[type].stretching_stiffness;
    const Eigen::SparseMatrix<double> full = model.matrix().selfadjointView<Eigen::Lower>();
    const Eigen::MatrixXd modelled = Eigen::MatrixXd(full) - shift * Eigen::MatrixXd::Identity(n, n);
    const double h = 1e-4;
    Eigen::MatrixXd exact(n, n);
    Eigen::VectorXd gp(x.size()), gm(x.size());
    for (Index j = 0; j < n; ++j) {
      Eigen::VectorXd xp = x, xm = x;
      xp[3 * kOffset + j] += h;
      xm[3 * kOffset + j] -= h;
      f.valueAndGradient(xp, gp);
      f.valueAndGradient(xm, gm);
      exact.col(j) = (gp - gm).segment(3 * kOffset, n) / (2 * h);
    }
    EXPECT_LT((modelled - exact).cwiseAbs().maxCoeff(), 1e-6 * types[type].stretching_stiffness)
        << "type " << type << "\nmodel\n" << modelled << "\nfinite differences\n" << exact;
  }
}

// Random tangles with linkers, motors and branches, relaxed from the same start to 1e-4 pN
// (CG stalls on rounding near 1e-5) by conjugate gradients and by preconditioned L-BFGS:
// the same minimum energy. A tangle held by one bead can still turn about it, so
// positions are not unique; the energy is, up to F^2/(2 k_min) ~ (1e-4 pN)^2 /
// (2 * 1e-3 pN/nm) = 5e-6 pN nm at that residual (bound: 1e-4 pN nm, against energies of
// 10^2-10^3 pN nm). The held bead does not move.
TEST(FilamentPreconditioner, ChangesTheSpeedNotTheMinimum) {
  const std::vector<FilamentType> types = testTypes();
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const Network net = randomNetwork(seed);
    ForceField f = internalTerms(net.layout, types);
    std::vector<char> frozen(net.layout.num_beads, 0);
    frozen[3] = 1;
    std::vector<char> frozen_coordinates(3 * static_cast<std::size_t>(kOffset), 1);
    for (char b : frozen) frozen_coordinates.insert(frozen_coordinates.end(), 3, b);
    f.setFrozen(frozen_coordinates);
    const Eigen::VectorXd start = Eigen::Map<const Eigen::VectorXd>(net.x.data(), static_cast<Eigen::Index>(net.x.size()));

    MinimizerSettings cg;
    cg.kind = MinimizerKind::kConjugateGradient;
    cg.force_tolerance = 1e-4;
    Eigen::VectorXd x_cg = start;
    const MinimizationResult by_cg = minimize(f, x_cg, cg);
    ASSERT_TRUE(by_cg.converged) << "seed " << seed << ": " << by_cg.stop_reason << " after " << by_cg.iterations << " iterations, max force " << by_cg.max_force;

    FilamentPreconditioner model;
    ASSERT_TRUE(model.build(net.layout, types, start, frozen));
    MinimizerSettings pre = cg;
    pre.kind = MinimizerKind::kLbfgs;
    pre.inverse_hessian = [&model](const Eigen::VectorXd& r, Eigen::VectorXd& z) { model.apply(r, z); };
    Eigen::VectorXd x_pre = start;
    const MinimizationResult by_pre = minimize(f, x_pre, pre);
    ASSERT_TRUE(by_pre.converged) << "seed " << seed << ": " << by_pre.stop_reason;

    EXPECT_NEAR(by_pre.energy, by_cg.energy, 1e-4) << "seed " << seed;
    EXPECT_EQ(x_pre.segment<3>(3 * (kOffset + 3)), start.segment<3>(3 * (kOffset + 3))) << "seed " << seed;
    std::printf("seed %u: energy %.9g (CG) %.9g (preconditioned L-BFGS); iterations %ld, %ld\n", seed, by_cg.energy,
                by_pre.energy, by_cg.iterations, by_pre.iterations);
  }
}

}  // namespace
}  // namespace cortex
