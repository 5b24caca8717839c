// Next-event times of all compartments, earliest first: a two-level queue.
//
// Compartments are grouped in blocks of 32 consecutive ids; the times live in one flat
// array, and an IndexedHeap orders the blocks by their earliest time. A single heap over
// 10^5 compartments spends its time in chains of dependent cache misses (each level of a
// sift waits for the previous one); here the block heap is 32 times smaller and stays in
// cache, and the price is a scan of 32 contiguous times (four cache lines, fetched in
// parallel) when a block's earliest compartment moves later. Most updates (a hop's
// destination) touch no heap at all.
#pragma once

#include <vector>

#include "chem/indexed_heap.hpp"

namespace cortex {

class EventQueue {
 public:
  // Id i gets times[i].
  void assign(const std::vector<double>& times);

  Index topId() const { return earliest_[heap_.top().id]; }
  double topTime() const { return heap_.top().time; }
  double time(Index id) const { return times_[id]; }

  void update(Index id, double time) {
    times_[id] = time;
    const Index b = id / kBlock;
    if (time < heap_.time(b)) {
      earliest_[b] = id;
      heap_.update(b, time);
    } else if (earliest_[b] == id) {
      heap_.update(b, rescan(b));
    }
  }

  // update(topId(), time) for a time no earlier than topTime(): the compartment that
  // just fired.
  void replaceTop(double time) {
    const Index b = heap_.top().id;
    times_[earliest_[b]] = time;
    heap_.replaceTop(rescan(b));
  }

 private:
  static constexpr Index kBlock = 32;

  // Earliest time in block b, recording which compartment holds it (the first one on
  // ties, so the result is deterministic). Written with selects, not branches.
  double rescan(Index b) {
    const double* t = &times_[static_cast<std::size_t>(b) * kBlock];
    double best = t[0];
    Index arg = 0;
    for (Index k = 1; k < scan_; ++k) {
      const bool earlier = t[k] < best;
      best = earlier ? t[k] : best;
      arg = earlier ? k : arg;
    }
    earliest_[b] = b * kBlock + arg;
    return best;
  }

  Index scan_ = kBlock;          // entries per block worth scanning: fewer on a tiny grid
  std::vector<double> times_;    // padded to whole blocks with +inf
  std::vector<Index> earliest_;  // per block: the compartment with the earliest time
  std::vector<double> block_times_;
  IndexedHeap heap_;
};

}  // namespace cortex
