// Filament force-field throughput: every filament term (stretching, bending, excluded
// volume, boundary, linkers, motors, branching) evaluated with its gradient.
//
// Scenarios (networks are built directly as layouts, straight filaments jittered by up
// to 1 nm so that bending is not trivially zero; actin defaults from filament_params.hpp):
//   actomyosin: MEDYAN's actomyosin benchmark scale, 30 filaments of 1-3 cylinders of
//     40 monomers x 2.7 nm in a 1000 x 1000 x 500 nm box, 20 linkers and 10 motors.
//   large: 2000 filaments x 5 cylinders (10,000 cylinders) in a 3 µm box, 1000 linkers,
//     200 motors and 100 branches.
// Positions are fixed between calls, as between minimizer steps shorter than skin/2, so
// the exclusion list is built once; `exclusion_rebuild` measures a forced rebuild.
// Throughput: bead_evals_per_s = beads x calls / wall second. The relaxation's Hessian
// model (filament_preconditioner.hpp): its build and factorization, once per relaxation,
// and one solve, once per L-BFGS iteration, beside a force evaluation of the same network.
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <random>

#include "filament/boundary_energy.hpp"
#include "filament/branch_energy.hpp"
#include "filament/excluded_volume_energy.hpp"
#include "filament/filament_bending_energy.hpp"
#include "filament/filament_preconditioner.hpp"
#include "filament/spring_energy.hpp"
#include "filament/stretching_energy.hpp"

namespace cortex {
namespace {

constexpr double kCylinderLength = 40 * 2.7;  // nm

struct Scenario {
  std::vector<FilamentType> types{FilamentType{}};
  FilamentLayout layout;
  BoundaryConfig boundary;
  std::vector<double> x;
};

Scenario makeScenario(int filaments, int min_cylinders, int max_cylinders, Vec3 box, int linkers, int motors,
                      int branches) {
  Scenario s;
  s.boundary.max = box;
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::vector<Index> first_cylinder;
  Index bead = 0;
  for (int f = 0; f < filaments; ++f) {
    const int n = min_cylinders +
                  static_cast<int>(u(rng) * (max_cylinders - min_cylinders + 1)) % (max_cylinders - min_cylinders + 1);
    const double half = 0.5 * n * kCylinderLength;
    const Vec3 dir = Vec3(gauss(rng), gauss(rng), gauss(rng)).normalized();
    Vec3 center;
    for (int k = 0; k < 3; ++k) center[k] = half + std::max(0.0, box[k] - 2.0 * half) * u(rng);
    first_cylinder.push_back(static_cast<Index>(s.layout.cylinders.size()));
    for (int b = 0; b <= n; ++b) {
      const Vec3 p = center + (b * kCylinderLength - half) * dir + Vec3(u(rng), u(rng), u(rng));
      s.x.insert(s.x.end(), {p.x(), p.y(), p.z()});
      if (b < n) s.layout.cylinders.push_back({bead + b, bead + b + 1, f, 0, kCylinderLength});
      if (b >= 1 && b < n) s.layout.hinges.push_back({bead + b - 1, bead + b, bead + b + 1, 0});
    }
    bead += n + 1;
  }
  s.layout.num_beads = bead;
  s.layout.version = 1;
  const auto& cyl = s.layout.cylinders;
  auto point = [&] {
    const Cylinder& c = cyl[static_cast<std::size_t>(u(rng) * static_cast<double>(cyl.size())) % cyl.size()];
    return CylinderPoint{c.bead0, c.bead1, u(rng)};
  };
  auto spring = [&](double k) {
    Spring sp{point(), point(), k, 0.0};
    sp.rest_length = 0.9 * std::abs(springTension({sp.a, sp.b, 1.0, 0.0}, s.x.data(), 0));
    return sp;
  };
  for (int i = 0; i < linkers; ++i) s.layout.linkers.push_back(spring(8.0));
  for (int i = 0; i < motors; ++i) s.layout.motors.push_back(spring(2.5));
  for (int i = 0; i < branches && 2 * i + 1 < filaments; ++i) {
    const Cylinder& daughter = cyl[first_cylinder[2 * i + 1]];
    s.layout.branches.push_back({{cyl[first_cylinder[2 * i]].bead0, cyl[first_cylinder[2 * i]].bead1, 0.5},
                                 daughter.bead0,
                                 daughter.bead1,
                                 100.0,
                                 100.0,
                                 std::cos(70.0 * std::numbers::pi / 180.0)});
  }
  return s;
}

Scenario actomyosin() { return makeScenario(30, 1, 3, Vec3(1000, 1000, 500), 20, 10, 0); }
Scenario large() { return makeScenario(2000, 5, 5, Vec3(3000, 3000, 3000), 1000, 200, 100); }

std::vector<std::unique_ptr<EnergyTerm>> allTerms(const Scenario& s) {
  std::vector<std::unique_ptr<EnergyTerm>> terms;
  terms.push_back(std::make_unique<FilamentStretchingEnergy>(s.layout, s.types));
  terms.push_back(std::make_unique<FilamentBendingEnergy>(s.layout, s.types));
  terms.push_back(std::make_unique<CylinderExclusionEnergy>(s.layout, s.types));
  terms.push_back(std::make_unique<BoundaryRepulsionEnergy>(s.layout, s.boundary));
  terms.push_back(std::make_unique<SpringEnergy>(s.layout, s.layout.linkers, "linkers"));
  terms.push_back(std::make_unique<SpringEnergy>(s.layout, s.layout.motors, "motors"));
  terms.push_back(std::make_unique<BranchEnergy>(s.layout));
  return terms;
}

void setThroughput(benchmark::State& state, const Scenario& s) {
  state.counters["beads"] = static_cast<double>(s.layout.num_beads);
  state.counters["cylinders"] = static_cast<double>(s.layout.cylinders.size());
  state.counters["bead_evals_per_s"] = benchmark::Counter(
      static_cast<double>(s.layout.num_beads) * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

// The whole filament force field, gradient zeroed each call as ForceField does.
void BM_FilamentField(benchmark::State& state, Scenario (*make)()) {
  const Scenario s = make();
  auto terms = allTerms(s);
  std::vector<double> gradient(s.x.size());
  std::uint64_t version = 0;
  for (auto _ : state) {
    std::fill(gradient.begin(), gradient.end(), 0.0);
    double energy = 0.0;
    const Evaluation e{s.x.data(), gradient.data(), ++version};
    for (auto& t : terms) energy += t->evaluate(e);
    benchmark::DoNotOptimize(energy);
    benchmark::ClobberMemory();
  }
  state.counters["exclusion_pairs"] =
      static_cast<double>(static_cast<CylinderExclusionEnergy&>(*terms[2]).listedPairs());
  setThroughput(state, s);
}

// One term alone on the large network (index into allTerms' order).
void BM_FilamentTerm(benchmark::State& state, std::size_t index) {
  const Scenario s = large();
  auto terms = allTerms(s);
  EnergyTerm& term = *terms[index];
  std::vector<double> gradient(s.x.size(), 0.0);
  std::uint64_t version = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(term.evaluate({s.x.data(), gradient.data(), ++version}));
    benchmark::ClobberMemory();
  }
  state.SetLabel(term.name());
  setThroughput(state, s);
}

// The exclusion neighbour list rebuilt on every call (a new layout version each time),
// plus one evaluation: the cost after every chemistry step that changes the network.
void BM_ExclusionRebuild(benchmark::State& state, Scenario (*make)()) {
  Scenario s = make();
  CylinderExclusionEnergy term(s.layout, s.types);
  std::vector<double> gradient(s.x.size(), 0.0);
  for (auto _ : state) {
    ++s.layout.version;
    benchmark::DoNotOptimize(term.evaluate({s.x.data(), gradient.data(), s.layout.version}));
  }
  state.counters["exclusion_pairs"] = static_cast<double>(term.listedPairs());
  setThroughput(state, s);
}

// The model built and factorized at the network's positions (no frozen beads).
void BM_PreconditionerBuild(benchmark::State& state, Scenario (*make)()) {
  const Scenario s = make();
  const Eigen::VectorXd x = Eigen::Map<const Eigen::VectorXd>(s.x.data(), static_cast<Eigen::Index>(s.x.size()));
  const std::vector<char> frozen(static_cast<std::size_t>(s.layout.num_beads), 0);
  for (auto _ : state) {
    FilamentPreconditioner model;
    benchmark::DoNotOptimize(model.build(s.layout, s.types, x, frozen));
  }
  setThroughput(state, s);
}

// One solve P z = r with the factor built once.
void BM_PreconditionerApply(benchmark::State& state, Scenario (*make)()) {
  const Scenario s = make();
  const Eigen::VectorXd x = Eigen::Map<const Eigen::VectorXd>(s.x.data(), static_cast<Eigen::Index>(s.x.size()));
  FilamentPreconditioner model;
  if (!model.build(s.layout, s.types, x, std::vector<char>(static_cast<std::size_t>(s.layout.num_beads), 0))) {
    state.SkipWithError("the model did not factorize");
    return;
  }
  const Eigen::VectorXd r = Eigen::VectorXd::Ones(x.size());
  Eigen::VectorXd z;
  for (auto _ : state) {
    model.apply(r, z);
    benchmark::DoNotOptimize(z.data());
  }
  setThroughput(state, s);
}

BENCHMARK_CAPTURE(BM_FilamentField, actomyosin, actomyosin)->UseRealTime()->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_FilamentField, large, large)->UseRealTime()->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_FilamentTerm, large_stretching, 0)->UseRealTime()->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_FilamentTerm, large_bending, 1)->UseRealTime()->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_FilamentTerm, large_excluded_volume, 2)->UseRealTime()->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_FilamentTerm, large_boundary, 3)->UseRealTime()->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_ExclusionRebuild, actomyosin, actomyosin)->UseRealTime()->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_ExclusionRebuild, large, large)->UseRealTime()->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_PreconditionerBuild, actomyosin, actomyosin)->UseRealTime()->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_PreconditionerBuild, large, large)->UseRealTime()->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_PreconditionerApply, actomyosin, actomyosin)->UseRealTime()->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_PreconditionerApply, large, large)->UseRealTime()->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace cortex

BENCHMARK_MAIN();
