#include "chem/subvolume_graph.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace cortex {

Index reverseEdge(const SubvolumeGraph& g, Index from, Index e) {
  const Index j = g.target[e];
  const auto end = g.target.begin() + g.start[j + 1];
  const auto back = std::find(g.target.begin() + g.start[j], end, from);
  return back == end ? -1 : static_cast<Index>(back - g.target.begin());
}

void validate(const SubvolumeGraph& g, const std::string& what) {
  auto fail = [&](const std::string& why) { throw InputError(what + ": " + why); };
  const Index n = g.count();
  if (static_cast<Index>(g.start.size()) != n + 1 || g.start.front() != 0 || g.start.back() != g.numEdges() ||
      g.hop_length2.size() != g.target.size())
    fail("edge arrays do not match the subvolumes");
  for (Index i = 0; i < n; ++i) {
    if (!(g.size[i] > 0.0) || !std::isfinite(g.size[i])) fail("subvolume " + std::to_string(i) + " has no size");
    if (g.start[i + 1] < g.start[i]) fail("edge offsets decrease");
  }
  for (Index i = 0; i < n; ++i)
    for (Index e = g.start[i]; e < g.start[i + 1]; ++e) {
      const Index j = g.target[e];
      if (j < 0 || j >= n || j == i) fail("edge " + std::to_string(e) + " leads nowhere");
      if (!(g.hop_length2[e] > 0.0) || !std::isfinite(g.hop_length2[e]))
        fail("edge " + std::to_string(e) + " has no hop length");
      const Index back = reverseEdge(g, i, e);
      if (back < 0) fail("edge " + std::to_string(e) + " has no reverse");
      const double forward = g.size[i] / g.hop_length2[e];
      const double reverse = g.size[j] / g.hop_length2[back];
      if (std::abs(forward - reverse) > 1e-9 * std::max(forward, reverse))
        fail("edge " + std::to_string(e) + " breaks detailed balance (size / l^2 not symmetric)");
    }
  if (g.lattice == std::array<int, 3>{0, 0, 0}) return;
  const auto [nx, ny, nz] = g.lattice;
  if (nx < 1 || ny < 1 || nz < 1 || static_cast<double>(nx) * ny * nz != n) fail("lattice shape does not match");
  Index i = 0;
  for (int z = 0; z < nz; ++z)
    for (int y = 0; y < ny; ++y)
      for (int x = 0; x < nx; ++x, ++i) {
        std::vector<Index> expected;
        for (const auto& [has, step] : {std::pair{x > 0, -1}, {x + 1 < nx, 1}, {y > 0, -nx}, {y + 1 < ny, nx},
                                        {z > 0, -nx * ny}, {z + 1 < nz, nx * ny}})
          if (has) expected.push_back(i + step);
        if (!std::equal(expected.begin(), expected.end(), g.target.begin() + g.start[i], g.target.begin() + g.start[i + 1]) ||
            static_cast<Index>(expected.size()) != g.start[i + 1] - g.start[i])
          fail("subvolume " + std::to_string(i) + " is not joined to its lattice neighbours in face order");
      }
}

}  // namespace cortex
