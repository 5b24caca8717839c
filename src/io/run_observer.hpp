// The RunObserver of a real run: snapshots to trajectory.h5/.xdmf, checkpoints, and
// progress in the log and on the terminal.
#pragma once

#include <chrono>
#include <filesystem>

#include "io/checkpoint.hpp"
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
                 double end_time, bool live_progress, const StopSignals* stop, RunInfo run);
  void onSnapshot(System& system) override;
  void onCheckpoint(const System& system) override;
  void onWindow(const System& system, const MinimizationResult& result) override;
  bool stopRequested() const override { return stop_ && stop_->requested(); }
  void finishProgress();
  // Time (s) of the last checkpoint this observer wrote; negative if none.
  double lastCheckpointTime() const { return last_checkpoint_; }

 private:
  std::filesystem::path outdir_;
  CheckpointHeader header_;
  TrajectoryWriter& writer_;
  double end_time_;
  bool live_;
  std::chrono::steady_clock::time_point start_, last_report_;
  double start_sim_time_ = -1.0;
  const StopSignals* stop_;
  RunInfo run_;
  double last_checkpoint_ = -1.0;
};

}  // namespace cortex
