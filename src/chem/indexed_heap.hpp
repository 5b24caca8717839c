// Indexed 4-ary min-heap of times, one entry per id (EventQueue keeps one over blocks
// of compartments).
//
// A sift is a chain of dependent memory accesses, so the layout matters more than the
// asymptotics: entries are 16 bytes and the array is offset so that the four children
// of a node fill exactly one 64-byte cache line. A sift then costs one memory access per
// level, over half the levels of a binary heap. The array is padded to whole sibling
// groups with +inf sentinels, so every level compares four children without bounds
// checks, and the comparisons are written as selects (their outcome is unpredictable).
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "core/types.hpp"

namespace cortex {

class IndexedHeap {
 public:
  struct alignas(16) Entry {
    double time;
    Index id;
  };

  IndexedHeap() = default;
  IndexedHeap(const IndexedHeap&) = delete;  // e_ points into storage_
  IndexedHeap& operator=(const IndexedHeap&) = delete;

  // Id i gets times[i]; O(n). Ties are broken by the deterministic heapify order.
  void assign(const std::vector<double>& times);

  const Entry& top() const { return e_[0]; }
  double time(Index id) const { return e_[pos_[id]].time; }

  void update(Index id, double time) {
    const Index p = pos_[id];
    const Entry x{time, id};
    if (time < e_[p].time)
      siftUp(p, x);
    else
      siftDown(p, x);
  }

  // Same as update(top().id, time), faster when the new time is late.
  void replaceTop(double time) { siftDownFromTop(0, Entry{time, e_[0].id}); }

 private:
  static constexpr double kInf = std::numeric_limits<double>::infinity();

  void place(Index p, const Entry& x) {
    e_[p] = x;
    pos_[x.id] = p;
  }

  void siftUp(Index p, const Entry& x) {
    while (p > 0) {
      const Index parent = (p - 1) >> 2;
      if (!(x.time < e_[parent].time)) break;
      place(p, e_[parent]);
      p = parent;
    }
    place(p, x);
  }

  // Index of the earliest of the four children starting at c, without branches (which
  // way a comparison of random times goes is unpredictable).
  Index minChild(Index c) const {
    const Index m01 = c + (e_[c + 1].time < e_[c].time);
    const Index m23 = c + 2 + (e_[c + 3].time < e_[c + 2].time);
    const bool right = e_[m23].time < e_[m01].time;
    return m01 + (m23 - m01) * right;
  }

  void siftDown(Index p, const Entry& x) {
    while (true) {
      const Index c = 4 * p + 1;
      if (c >= n_) break;
      // Sentinels (+inf) stand in for missing children, so all four are compared.
      const Index m = minChild(c);
      if (!(e_[m].time < x.time)) break;
      place(p, e_[m]);
      p = m;
    }
    place(p, x);
  }

  // Floyd's variant for a node whose new time is typically late (a compartment that just
  // fired): move the hole down to a leaf along the earliest children without comparing
  // with x, then sift x up the few levels it usually needs.
  void siftDownFromTop(Index p, const Entry& x) {
    while (true) {
      const Index c = 4 * p + 1;
      if (c >= n_) break;
      const Index m = minChild(c);  // never a sentinel: ties go to the lower, real, index
      place(p, e_[m]);
      p = m;
    }
    siftUp(p, x);
  }

  std::vector<Entry> storage_;
  Entry* e_ = nullptr;  // logical index 0, placed so that e_ + 1 is 64-byte aligned
  std::vector<Index> pos_;
  Index n_ = 0;
};

}  // namespace cortex
