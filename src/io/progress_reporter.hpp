// Progress of a run for the people watching it: on a terminal a line refreshed twice a
// second; off a terminal (a batch job) a plain line on stderr every `interval` seconds;
// in cortex.log a line every 30 s. Lines show simulated time, wall time, an ETA from the
// recent pace, where the time goes (mechanics and chemistry, with their throughput), and
// during a long relaxation how far it has come.
#pragma once

#include <chrono>
#include <deque>
#include <string>

#include "mech/minimizer.hpp"
#include "sim/system.hpp"

namespace cortex {

// The pace of a run over its recent past (the last `span` seconds of wall time), so an
// estimate of the time left follows a run that slows down or speeds up (a shrinking
// vesicle, a growing network) instead of extrapolating from its start.
class RecentPace {
 public:
  explicit RecentPace(double span_seconds = 60.0) : span_(span_seconds) {}
  void add(double wall, double sim_time);
  // Wall seconds to advance `remaining` simulated seconds at the recent pace; negative
  // when there is no pace yet.
  double secondsFor(double remaining) const;

 private:
  double span_;
  std::deque<std::pair<double, double>> samples_;  // (wall, simulated time)
};

class ProgressReporter {
 public:
  // `live`: stderr is a terminal (and not --quiet); `interval`: seconds between plain
  // lines off a terminal, 0 for none; `at_start`: the counters when this session began
  // (a resumed run's carry the time spent before it), so that the shares of wall time are
  // this session's.
  ProgressReporter(double end_time, bool live, double interval, const RunCounters& at_start);

  void window(const System& system, const MinimizationResult& result);
  void relaxing(const System& system, const std::string& what, const MinimizerProgress& p);
  // Ends the terminal line.
  void finish();

 private:
  double wallSeconds() const;
  // Which channels to write at `wall`: each whose interval has passed (all when `now`); a
  // relaxation line also needs a whole interval since the last window ended.
  struct Due {
    bool live, plain, log;
    bool any() const { return live || plain || log; }
  };
  Due due(double wall, bool now, bool relaxing) const;
  void show(const std::string& line, const Due& due, double wall);

  double end_time_;
  bool live_;
  double interval_;
  std::chrono::steady_clock::time_point start_;
  double last_live_ = -1e300, last_plain_ = 0.0, last_log_ = 0.0;  // wall seconds
  double last_window_ = 0.0;  // wall seconds when the latest window ended
  bool line_open_ = false;
  RecentPace pace_;
  RunCounters at_start_;
};

}  // namespace cortex
