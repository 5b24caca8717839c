#include "chem/event_queue.hpp"

#include <algorithm>
#include <limits>

namespace cortex {

void EventQueue::assign(const std::vector<double>& times) {
  const Index blocks = (static_cast<Index>(times.size()) + kBlock - 1) / kBlock;
  times_.assign(static_cast<std::size_t>(blocks) * kBlock, std::numeric_limits<double>::infinity());
  std::copy(times.begin(), times.end(), times_.begin());
  scan_ = std::min(kBlock, std::max<Index>(1, static_cast<Index>(times.size())));
  earliest_.resize(blocks);
  block_times_.resize(blocks);
  for (Index b = 0; b < blocks; ++b) block_times_[b] = rescan(b);
  heap_.assign(block_times_);
}

}  // namespace cortex
