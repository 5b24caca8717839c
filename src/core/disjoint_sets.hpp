// Disjoint sets of the indices 0 .. n-1 (union–find with path halving). Joining keeps the
// lower root, so which index stands for a set does not depend on the order of joins.
#pragma once

#include <algorithm>
#include <numeric>
#include <vector>

#include "core/types.hpp"

namespace cortex {

class DisjointSets {
 public:
  explicit DisjointSets(Index n) : parent_(static_cast<std::size_t>(n)) {
    std::iota(parent_.begin(), parent_.end(), Index{0});
  }
  // The lowest index of i's set joined so far (its representative).
  Index root(Index i) {
    while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
    return i;
  }
  void join(Index a, Index b) {
    const Index ra = root(a), rb = root(b);
    parent_[std::max(ra, rb)] = std::min(ra, rb);
  }

 private:
  std::vector<Index> parent_;
};

}  // namespace cortex
