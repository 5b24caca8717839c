#include "io/progress_reporter.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <cstdio>

namespace cortex {
namespace {

constexpr double kLiveInterval = 0.5;  // s between terminal refreshes
constexpr double kLogInterval = 30.0;  // s between log lines

std::string duration(double seconds) {
  if (seconds < 0) return "?";
  if (seconds < 120) return fmt::format("{:.0f} s", seconds);
  if (seconds < 7200) return fmt::format("{:.0f} min", seconds / 60);
  return fmt::format("{:.1f} h", seconds / 3600);
}

// "mechanics 64% (12,345 force evaluations, 210/s)": the share of this session's wall time
// (the counters' seconds less those at its start) and the throughput since t = 0.
std::string throughput(const System& system, const RunCounters& at_start, double wall) {
  const RunCounters& c = system.counters;
  const double mechanics_share = (c.mechanics_seconds - at_start.mechanics_seconds) / wall;
  const double chemistry_share = (c.chemistry_seconds - at_start.chemistry_seconds) / wall;
  std::string text;
  const std::int64_t evaluations = system.forceField().forceEvaluations();
  if (system.hasMechanics() && evaluations > 0)
    text += fmt::format(" | mechanics {:.0f}% ({} force evaluations, {:.3g}/s)", 100 * mechanics_share,
                        evaluations, c.mechanics_seconds > 0 ? evaluations / c.mechanics_seconds : 0.0);
  if (const ChemistryEngine* chem = system.chemistry())
    text += fmt::format(" | chemistry {:.0f}% ({} events, {:.3g} events/s)", 100 * chemistry_share,
                        chem->events(), c.chemistry_seconds > 0 ? chem->events() / c.chemistry_seconds : 0.0);
  return text;
}

}  // namespace

void RecentPace::add(double wall, double sim_time) {
  samples_.emplace_back(wall, sim_time);
  // Keep one sample older than the span, so the pace always spans at least `span_`.
  while (samples_.size() > 2 && samples_[1].first < wall - span_) samples_.pop_front();
}

double RecentPace::secondsFor(double remaining) const {
  if (samples_.size() < 2) return -1.0;
  const double wall = samples_.back().first - samples_.front().first;
  const double sim = samples_.back().second - samples_.front().second;
  return sim > 0 ? remaining * wall / sim : -1.0;
}

ProgressReporter::ProgressReporter(double end_time, bool live, double interval, const RunCounters& at_start)
    : end_time_(end_time),
      live_(live),
      interval_(interval),
      start_(std::chrono::steady_clock::now()),
      at_start_(at_start) {}

double ProgressReporter::wallSeconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

ProgressReporter::Due ProgressReporter::due(double wall, bool now, bool relaxing) const {
  // A relaxation is reported only once it has run a whole interval without a window ending.
  const auto passed = [&](double last, double interval) {
    return now || (wall - last >= interval && (!relaxing || wall - last_window_ >= interval));
  };
  return {live_ && passed(last_live_, kLiveInterval), !live_ && interval_ > 0 && passed(last_plain_, interval_),
          passed(last_log_, kLogInterval)};
}

void ProgressReporter::show(const std::string& line, const Due& due, double wall) {
  if (due.live) {
    std::fprintf(stderr, "\r%-150s", line.c_str());
    std::fflush(stderr);
    line_open_ = true;
    last_live_ = wall;
  }
  if (due.plain) {
    std::fprintf(stderr, "cortex: %s\n", line.c_str());
    std::fflush(stderr);
    last_plain_ = wall;
  }
  if (due.log) {
    spdlog::info("{}", line);
    last_log_ = wall;
  }
}

void ProgressReporter::window(const System& system, const MinimizationResult& result) {
  const double wall = wallSeconds();
  pace_.add(wall, system.time());
  const bool done = system.time() >= end_time_;
  std::string line = fmt::format("t = {:.4g} / {:.4g} s ({:.0f}%) | wall {}, {} left", system.time(), end_time_,
                                 end_time_ > 0 ? 100 * system.time() / end_time_ : 100.0, duration(wall),
                                 duration(done ? 0.0 : pace_.secondsFor(end_time_ - system.time())));
  line += throughput(system, at_start_, wall);
  if (system.hasMechanics())
    line += fmt::format(" | last relaxation {} iterations, max force {:.3g} pN", result.iterations, result.max_force);
  show(line, due(wall, done, false), wall);
  last_window_ = wall;
}

void ProgressReporter::relaxing(const System& system, const std::string& what, const MinimizerProgress& p) {
  const double wall = wallSeconds();
  const Due channels = due(wall, false, true);
  if (!channels.any()) return;  // the common case: this runs every minimizer iteration
  show(fmt::format("t = {:.4g} / {:.4g} s | wall {} | relaxing {}: {} iterations, max force {:.3g} pN (tolerance "
                   "{:.3g} pN)",
                   system.time(), end_time_, duration(wall), what, p.iterations, p.max_force, p.tolerance),
       channels, wall);
}

void ProgressReporter::finish() {
  if (line_open_) std::fprintf(stderr, "\n");
  line_open_ = false;
}

}  // namespace cortex
