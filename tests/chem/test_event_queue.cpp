// The next-subvolume method's priority queues against a linear scan, under random
// updates of the kinds the engine makes (earlier, later, to and from +inf, fired top).
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

#include "chem/event_queue.hpp"
#include "core/random.hpp"

namespace cortex {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

template <class Queue>
void checkAgainstScan(Queue& q, int n, std::uint64_t seed) {
  RandomStream rng(seed, StreamId::kInitialConditions);
  std::vector<double> times(n);
  for (double& t : times) t = rng.uniform() < 0.1 ? kInf : rng.uniform();
  q.assign(times);
  double now = 0.0;
  for (int step = 0; step < 20000; ++step) {
    const double earliest = *std::min_element(times.begin(), times.end());
    ASSERT_EQ(q.topTime(), earliest) << "step " << step;
    ASSERT_EQ(times[q.topId()], earliest);
    const double u = rng.uniform();
    if (u < 0.5 && earliest < kInf) {  // the top fires and moves later
      now = earliest;
      const double later = rng.uniform() < 0.05 ? kInf : now + rng.uniform();
      times[q.topId()] = later;
      q.replaceTop(later);
    } else {
      const Index id = static_cast<Index>(rng.uniform() * n);
      const double t = rng.uniform() < 0.05 ? kInf : now + rng.uniform();
      times[id] = t;
      q.update(id, t);
      ASSERT_EQ(q.time(id), t);
    }
  }
}

// Adapter with the EventQueue interface over a bare IndexedHeap.
struct HeapQueue {
  IndexedHeap heap;
  void assign(const std::vector<double>& t) { heap.assign(t); }
  double topTime() const { return heap.top().time; }
  Index topId() const { return heap.top().id; }
  double time(Index id) const { return heap.time(id); }
  void update(Index id, double t) { heap.update(id, t); }
  void replaceTop(double t) { heap.replaceTop(t); }
};

TEST(EventQueue, AlwaysYieldsTheEarliestTime) {
  for (int n : {1, 2, 31, 32, 33, 1000}) {
    EventQueue q;
    checkAgainstScan(q, n, 100 + n);
  }
}

TEST(IndexedHeap, AlwaysYieldsTheEarliestTime) {
  for (int n : {1, 2, 4, 5, 6, 17, 1000}) {
    HeapQueue q;
    checkAgainstScan(q, n, 200 + n);
  }
}

}  // namespace
}  // namespace cortex
