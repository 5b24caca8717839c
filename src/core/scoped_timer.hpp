// Wall-clock accounting for the run log's breakdowns (force, solve, remesh seconds).
#pragma once

#include <chrono>

namespace cortex {

using SteadyClock = std::chrono::steady_clock;

inline double secondsSince(SteadyClock::time_point t) {
  return std::chrono::duration<double>(SteadyClock::now() - t).count();
}

// Adds the seconds since construction to `total` when it goes out of scope.
struct ScopedTimer {
  double& total;
  SteadyClock::time_point start = SteadyClock::now();
  ~ScopedTimer() { total += secondsSince(start); }
};

}  // namespace cortex
