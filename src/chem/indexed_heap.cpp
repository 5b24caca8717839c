#include "chem/indexed_heap.hpp"

#include <cstdint>

namespace cortex {

void IndexedHeap::assign(const std::vector<double>& times) {
  n_ = static_cast<Index>(times.size());
  // Children of p are 4p+1 .. 4p+4, so with e_ + 1 on a cache-line boundary every
  // sibling group is one line. Slack: up to 3 entries of shift, 4 of sentinel padding.
  storage_.assign(static_cast<std::size_t>(n_) + 8, Entry{kInf, -1});
  const auto address = reinterpret_cast<std::uintptr_t>(storage_.data() + 1);
  e_ = storage_.data() + (64 - address % 64) % 64 / sizeof(Entry);
  pos_.resize(n_);
  for (Index i = 0; i < n_; ++i) place(i, Entry{times[i], i});
  if (n_ > 1)
    for (Index p = (n_ - 2) / 4; p >= 0; --p) siftDown(p, Entry(e_[p]));
}

}  // namespace cortex
