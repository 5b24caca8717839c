// The RunObserver of a real run: snapshots to trajectory.h5/.xdmf, checkpoints, and
// progress in the log and on the terminal.
#pragma once

#include <chrono>
#include <filesystem>
#include <optional>

#include "io/checkpoint.hpp"
#include "io/progress_reporter.hpp"
#include "io/stop_signals.hpp"
#include "io/summary.hpp"
#include "io/trajectory_writer.hpp"
#include "sim/simulation.hpp"

namespace cortex {

class OutputObserver final : public RunObserver {
 public:
  // `stop` (may be null): signals that ask the run to stop.
  // `run` gives the seed and threads recorded with each snapshot's observables.
  OutputObserver(std::filesystem::path outdir, CheckpointHeader header, TrajectoryWriter& writer,
                 ProgressReporter& progress, const StopSignals* stop, RunInfo run);
  void onSnapshot(System& system) override;
  void onCheckpoint(const System& system) override;
  void onWindow(const System& system, const MinimizationResult& result) override;
  void onRelaxing(const System& system, const std::string& what, const MinimizerProgress& p) override;
  bool stopRequested() const override { return stop_ && stop_->requested(); }
  // A stop request waits for the window to end, up to kStopGraceSeconds after it was
  // first seen here; past that the window is abandoned (RunStopped). A batch system's
  // grace period before SIGKILL is often 30 s (Slurm's KillWait): the run still ends on
  // its own terms, with the trajectory index brought up to date.
  void duringWindow() override;
  static constexpr double kStopGraceSeconds = 10.0;
  // Time (s) of the last checkpoint this observer wrote; negative if none.
  double lastCheckpointTime() const { return last_checkpoint_; }

 private:
  std::filesystem::path outdir_;
  CheckpointHeader header_;
  TrajectoryWriter& writer_;
  ProgressReporter& progress_;
  std::chrono::steady_clock::time_point start_;
  const StopSignals* stop_;
  RunInfo run_;
  double last_checkpoint_ = -1.0;
  std::optional<std::chrono::steady_clock::time_point> stop_seen_;
};

}  // namespace cortex
