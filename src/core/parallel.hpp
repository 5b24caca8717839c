// Parallel loops whose results do not depend on the number of threads.
//
// Floating-point sums are split into fixed-size chunks, each summed in order, and the
// chunk sums added in order, so a run is bit-identical for any thread count.
#pragma once

#include <algorithm>
#include <vector>

#include "core/types.hpp"

namespace cortex {

// Below this many items a loop runs on one thread: opening a parallel region costs more
// than the work, and on a loaded machine waiting threads make it far worse.
inline constexpr Index kMinParallelItems = 4096;

template <class F>
void parallelFor(Index n, F&& body) {
#pragma omp parallel for schedule(static) if (n >= kMinParallelItems)
  for (Index i = 0; i < n; ++i) body(i);
}

template <class F>
double deterministicSum(Index n, F&& term) {
  constexpr Index kChunk = 2048;
  const Index chunks = (n + kChunk - 1) / kChunk;
  std::vector<double> partial(static_cast<std::size_t>(chunks), 0.0);
#pragma omp parallel for schedule(static) if (n >= kMinParallelItems)
  for (Index c = 0; c < chunks; ++c) {
    double s = 0.0;
    const Index end = std::min(n, (c + 1) * kChunk);
    for (Index i = c * kChunk; i < end; ++i) s += term(i);
    partial[c] = s;
  }
  double total = 0.0;
  for (double s : partial) total += s;
  return total;
}

}  // namespace cortex
