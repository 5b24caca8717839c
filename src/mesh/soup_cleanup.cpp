#include "mesh/soup_cleanup.hpp"

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <utility>
#include <vector>

#include "core/disjoint_sets.hpp"

namespace cortex {

void dropUnreferencedVertices(TriangleSoup& soup) {
  std::vector<Index> new_index(soup.positions.size(), -1);
  for (const Tri& t : soup.triangles) {
    for (Index v : t) new_index[v] = 0;
  }
  std::vector<Vec3> kept;
  for (std::size_t v = 0; v < new_index.size(); ++v) {
    if (new_index[v] < 0) continue;
    new_index[v] = Index(kept.size());
    kept.push_back(soup.positions[v]);
  }
  for (Tri& t : soup.triangles) {
    for (Index& v : t) v = new_index[v];
  }
  soup.positions = std::move(kept);
}

void weldCloseVertices(TriangleSoup& soup, double tol) {
  const std::vector<Vec3>& x = soup.positions;
  std::vector<Index> order(x.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](Index a, Index b) { return x[a].x() < x[b].x(); });
  DisjointSets welded(static_cast<Index>(x.size()));  // the lowest index of each survives: deterministic
  bool merged = false;
  for (std::size_t a = 0; a < order.size(); ++a) {
    const Index i = order[a];
    for (std::size_t b = a + 1; b < order.size() && x[order[b]].x() - x[i].x() <= tol; ++b) {
      const Index j = order[b];
      if ((x[j] - x[i]).norm() > tol) continue;
      welded.join(i, j);
      merged = true;
    }
  }
  if (!merged) return;
  std::vector<Tri> kept;
  for (Tri t : soup.triangles) {
    for (Index& v : t) v = welded.root(v);
    if (t[0] != t[1] && t[1] != t[2] && t[2] != t[0]) kept.push_back(t);
  }
  soup.triangles = std::move(kept);
  dropUnreferencedVertices(soup);
}

}  // namespace cortex
