// The membrane–filament exclusion's kernel, ∫ dS/d⁴ over a triangle with its gradient
// (interact/triangle_inverse_fourth.hpp), for bead–triangle pairs like a relaxation's:
// beads 1–20 nm over 10 nm triangles, feet inside and outside. Pairs per second for the
// value alone, with the gradient on the bead alone, and on the bead and the three vertices.
//   OMP_NUM_THREADS=1 build/bench/bench_triangle_integral
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "interact/triangle_inverse_fourth.hpp"

namespace cortex {
namespace {

struct PairSample {
  Vec3 p, a, b, c;
};

std::vector<PairSample> samples() {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> in_plane(-15.0, 15.0), height(1.0, 20.0), jitter(-2.0, 2.0);
  std::vector<PairSample> out(4096);
  for (PairSample& s : out) {
    s.a = Vec3(jitter(rng), jitter(rng), 0.0);
    s.b = Vec3(10.0 + jitter(rng), jitter(rng), 0.0);
    s.c = Vec3(jitter(rng), 10.0 + jitter(rng), 0.0);
    s.p = Vec3(in_plane(rng), in_plane(rng), height(rng));
  }
  return out;
}

void BM_TriangleIntegral(benchmark::State& state) {
  const std::vector<PairSample> pairs = samples();
  double sum = 0.0;
  for (auto _ : state)
    for (const PairSample& s : pairs) sum += triangleInverseFourth(s.p, s.a, s.b, s.c);
  benchmark::DoNotOptimize(sum);
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(pairs.size()));
}

// Arg: which gradient (InverseFourthGradient): 0 the bead's alone (a filament relaxed
// under a held membrane), 1 the bead's and the vertices'.
void BM_TriangleIntegralWithGradient(benchmark::State& state) {
  const auto which = static_cast<InverseFourthGradient>(state.range(0));
  const std::vector<PairSample> pairs = samples();
  double sum = 0.0;
  for (auto _ : state)
    for (const PairSample& s : pairs) {
      const TriangleInverseFourth r = triangleInverseFourthWithGradient(s.p, s.a, s.b, s.c, which);
      sum += r.value + r.d_point.x() + r.d_vertices[0].x();
    }
  benchmark::DoNotOptimize(sum);
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(pairs.size()));
}

BENCHMARK(BM_TriangleIntegral)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_TriangleIntegralWithGradient)
    ->Arg(static_cast<int>(InverseFourthGradient::kPoint))
    ->Arg(static_cast<int>(InverseFourthGradient::kAll))
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace cortex

BENCHMARK_MAIN();
