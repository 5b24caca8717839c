#include "io/run_observer.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "core/error.hpp"
#include "io/observables.hpp"
#include "mesh/mesh_quality.hpp"
#include "sim/frame_builder.hpp"

namespace cortex {
namespace {

void logFilaments(const System& system) {
  const FilamentNetwork* net = system.filaments();
  if (!net) return;
  const FilamentChemistry* chem = system.filamentChemistry();
  spdlog::info("t = {:.6g} s, filaments: {}, total length {:.4g} um; bound: {} linkers, {} motors; {} branches; "
               "max end load {:.3g} pN",
               system.time(), net->filaments().size(), net->totalLength() * 1e-3, net->linkers().size(),
               net->motors().size(), net->branches().size(), chem ? chem->maxEndLoad() : 0.0);
}

}  // namespace

OutputObserver::OutputObserver(std::filesystem::path outdir, CheckpointHeader header,
                               TrajectoryWriter& writer, ProgressReporter& progress, const StopSignals* stop,
                               RunInfo run)
    : outdir_(std::move(outdir)),
      header_(std::move(header)),
      writer_(writer),
      progress_(progress),
      start_(std::chrono::steady_clock::now()),
      stop_(stop),
      run_(run) {}

void OutputObserver::onSnapshot(System& system) {
  Frame frame = makeFrame(system);
  RunInfo now = run_;
  now.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  frame.observables = observableRow(summarize(system, now));
  writer_.write(frame);
  spdlog::debug("snapshot {} written at t = {:.6g} s", writer_.nextIndex() - 1, system.time());
  for (const auto& m : system.membranes()) {
    const MeshQuality q = measureQuality(m->mesh());
    const RemeshStats& r = m->remeshTotals();
    spdlog::info("t = {:.6g} s, membrane \"{}\": {} vertices; min angle {:.1f} deg, max aspect {:.2f}, "
                 "min dihedral cos {:.3f}; remeshing so far: {} splits, {} collapses, {} flips",
                 system.time(), m->name(), m->mesh().numVertices(), q.min_angle_deg, q.max_aspect_ratio,
                 q.min_dihedral_cos, r.splits, r.collapses, r.flips);
  }
  logFilaments(system);
}

void OutputObserver::onCheckpoint(const System& system) {
  header_.next_snapshot = writer_.nextIndex();
  writeCheckpoint(outdir_ / "checkpoint.h5", header_, system.state());
  last_checkpoint_ = system.time();
}

void OutputObserver::onWindow(const System& system, const MinimizationResult& result) {
  progress_.window(system, result);
}

void OutputObserver::duringWindow() {
  if (!stopRequested()) return;
  const auto now = std::chrono::steady_clock::now();
  if (!stop_seen_) stop_seen_ = now;
  const double waited = std::chrono::duration<double>(now - *stop_seen_).count();
  if (waited > kStopGraceSeconds)
    throw RunStopped(fmt::format("the window in progress was abandoned after the stop request waited {:.0f} s for it",
                                 waited));
}

void OutputObserver::onRelaxing(const System& system, const std::string& what, const MinimizerProgress& p) {
  progress_.relaxing(system, what, p);
}

}  // namespace cortex
