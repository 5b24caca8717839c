#include "mesh/soup_cleanup.hpp"

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <utility>
#include <vector>

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
  std::vector<Index> parent(x.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](Index v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  bool merged = false;
  for (std::size_t a = 0; a < order.size(); ++a) {
    const Index i = order[a];
    for (std::size_t b = a + 1; b < order.size() && x[order[b]].x() - x[i].x() <= tol; ++b) {
      const Index j = order[b];
      if ((x[j] - x[i]).norm() > tol) continue;
      const Index ri = root(i), rj = root(j);
      parent[std::max(ri, rj)] = std::min(ri, rj);  // lowest index survives: deterministic
      merged = true;
    }
  }
  if (!merged) return;
  std::vector<Tri> kept;
  for (Tri t : soup.triangles) {
    for (Index& v : t) v = root(v);
    if (t[0] != t[1] && t[1] != t[2] && t[2] != t[0]) kept.push_back(t);
  }
  soup.triangles = std::move(kept);
  dropUnreferencedVertices(soup);
}

}  // namespace cortex
