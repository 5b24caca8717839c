#include "io/run_observer.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <cstdio>

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
                               TrajectoryWriter& writer, double end_time, bool live_progress,
                               const StopSignals* stop, RunInfo run)
    : outdir_(std::move(outdir)),
      header_(std::move(header)),
      writer_(writer),
      end_time_(end_time),
      live_(live_progress),
      start_(std::chrono::steady_clock::now()),
      last_report_(start_),
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
  const auto now = std::chrono::steady_clock::now();
  if (start_sim_time_ < 0) start_sim_time_ = system.time();
  const double wall = std::chrono::duration<double>(now - start_).count();
  const bool done = system.time() >= end_time_;
  const double since = std::chrono::duration<double>(now - last_report_).count();
  // Terminal: refreshed twice a second; log file: a line every 30 s and at the end.
  if (!done && since < (live_ ? 0.5 : 30.0)) return;
  last_report_ = now;
  const double progressed = system.time() - start_sim_time_;
  const double eta = progressed > 0 ? wall * (end_time_ - system.time()) / progressed : 0.0;
  const double evals_per_s = system.counters.mechanics_seconds > 0
                                 ? system.forceField().forceEvaluations() /
                                       system.counters.mechanics_seconds
                                 : 0.0;
  std::string line = fmt::format("t = {:.4g} / {:.4g} s | wall {:.1f} s | ETA {:.0f} s", system.time(), end_time_,
                                 wall, eta);
  if (!system.membranes().empty())
    line += fmt::format(" | {} iterations, max force {:.3g} pN | {:.0f} force evaluations/s", result.iterations,
                        result.max_force, evals_per_s);
  if (const ChemistryEngine* chem = system.chemistry())
    line += fmt::format(" | {} events, {:.3g} events/s", chem->events(),
                        system.counters.chemistry_seconds > 0 ? chem->events() / system.counters.chemistry_seconds : 0.0);
  if (live_) {
    std::fprintf(stderr, "\r%-120s", line.c_str());
    std::fflush(stderr);
  } else {
    spdlog::info("{}", line);
  }
}

void OutputObserver::finishProgress() {
  if (live_) std::fprintf(stderr, "\n");
}

}  // namespace cortex
