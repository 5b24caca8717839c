#include "io/run_driver.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <omp.h>
#include <Eigen/Core>
#include <spdlog/sinks/basic_file_sink.h>
#include <spdlog/sinks/ringbuffer_sink.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <regex>

#include "core/error.hpp"
#include "core/hash.hpp"
#include "io/atomic_file.hpp"
#include "io/checkpoint.hpp"
#include "io/config.hpp"
#include "io/progress_reporter.hpp"
#include "io/run_observer.hpp"
#include "io/stop_signals.hpp"
#include "io/summary.hpp"
#include "io/trajectory_writer.hpp"
#include "sim/simulation.hpp"

namespace cortex {
namespace {

std::shared_ptr<spdlog::sinks::sink> warningsOnStderr() {
  auto console = std::make_shared<spdlog::sinks::stderr_color_sink_mt>();
  console->set_pattern("%^%l%$: %v");
  console->set_level(spdlog::level::warn);
  return console;
}

// Until the run's folder may be written (everything that can refuse the input comes
// first), messages go to stderr as they come and are kept for cortex.log: the set-up's
// warnings (a mesh too coarse for its shape, a flipped mesh) were on stderr only.
std::shared_ptr<spdlog::sinks::ringbuffer_sink_mt> logTheSetUp() {
  constexpr std::size_t kKept = 1000;
  auto kept = std::make_shared<spdlog::sinks::ringbuffer_sink_mt>(kKept);
  auto logger = std::make_shared<spdlog::logger>("cortex", spdlog::sinks_init_list{warningsOnStderr(), kept});
  logger->set_level(spdlog::level::debug);
  spdlog::set_default_logger(logger);
  return kept;
}

// `setup`: what logTheSetUp kept, written first.
void setUpLogging(const std::filesystem::path& outdir, bool append, spdlog::sinks::ringbuffer_sink_mt& setup) {
  auto console = warningsOnStderr();
  auto file = std::make_shared<spdlog::sinks::basic_file_sink_mt>((outdir / "cortex.log").string(), !append);
  file->set_pattern("[%Y-%m-%d %H:%M:%S.%e] %l: %v");
  for (const auto& message : setup.last_raw()) file->log(message);
  auto logger = std::make_shared<spdlog::logger>("cortex", spdlog::sinks_init_list{console, file});
  logger->set_level(spdlog::level::debug);
  logger->flush_on(spdlog::level::info);
  spdlog::set_default_logger(logger);
}

// What a run writes into its folder: a fresh run refuses a folder holding any of them
// (unless --overwrite, which removes exactly these).
const char* const kRunFiles[] = {"summary.json",      "checkpoint.h5",     "trajectory.h5",   "trajectory.xdmf",
                                 "observables.csv",   "cortex.log",        "snapshots",       "summary.json.tmp",
                                 "checkpoint.h5.tmp", "trajectory.h5.tmp", "trajectory.xdmf.tmp",
                                 "observables.csv.tmp", "compartments.h5",   "compartments.h5.tmp"};

// An entry of kRunFiles that cortex cannot have written: a folder where it writes a file,
// a file where it keeps its snapshot folder, or a device or socket.
void refuseForeignEntry(const std::filesystem::path& outdir, const std::string& name) {
  std::error_code ec;
  const auto status = std::filesystem::symlink_status(outdir / name, ec);
  if (!std::filesystem::exists(status)) return;
  const bool folder = name == "snapshots";
  if (folder ? std::filesystem::is_directory(status) : std::filesystem::is_regular_file(status)) return;
  throw InputError(fmt::format("{}: '{}' is not the {} cortex writes there; move it away", outdir.string(), name,
                               folder ? "folder" : "file"));
}

void prepareOutputFolder(const std::filesystem::path& outdir, bool overwrite) {
  std::error_code ec;
  const auto status = std::filesystem::status(outdir, ec);
  if (std::filesystem::exists(status) && !std::filesystem::is_directory(status))
    throw InputError(fmt::format("{}: the output folder is a file; give another -o", outdir.string()));
  std::filesystem::create_directories(outdir, ec);
  if (ec) throw InputError(fmt::format("{}: cannot create output folder: {}", outdir.string(), ec.message()));
  if (::access(outdir.c_str(), W_OK | X_OK) != 0)
    throw InputError(fmt::format("{}: cannot write into the output folder (permissions)", outdir.string()));
  std::vector<std::string> found;
  for (const char* name : kRunFiles)
    if (std::filesystem::exists(outdir / name, ec)) found.push_back(name);
  if (found.empty()) return;
  if (!overwrite)
    throw InputError(fmt::format("{}: holds the results of an earlier run ({}): give another -o, continue it with "
                                 "--resume {}, or replace them with --overwrite",
                                 outdir.string(), fmt::join(found, ", "), outdir.string()));
  // Only what cortex writes goes (the caller refused foreign entries first: remove_all
  // deleted a folder called cortex.log with everything in it), and the snapshot folder
  // keeps whatever is not a snapshot (TrajectoryWriter clears those).
  for (const std::string& name : found) {
    if (name == "snapshots") continue;
    std::filesystem::remove(outdir / name, ec);
    if (ec) throw InputError(fmt::format("{}: cannot remove {}: {}", outdir.string(), name, ec.message()));
  }
}

// Keys whose value the stored state was built from: a resume cannot honour a change, so
// it refuses one (the rest — rates, moduli, schedules, end_time — may change).
void refuseFrozenOverrides(const std::vector<std::string>& overrides) {
  static const std::regex frozen(
      R"(^(simulation\.(seed|chemistry_window)|compartments(\..*)?|chemistry\.engine|)"
      R"(membrane\.[0-9]+\.(name|shape|mesher|center|radius|radii|size|file|mesh_size|boundary|min_size|max_size|remesh_tolerance)|)"
      R"(membrane\.[0-9]+\.species\.[0-9]+\.(name|copies|density|region|footprint)|)"
      R"(species\.[0-9]+\.(name|copies|concentration|inside|outside)|reaction\.[0-9]+\.equation|)"
      R"(filament_type\.[0-9]+\.(name|monomer_species|monomer_size|cylinder_monomers)|filaments(\..*)?|)"
      R"((linker|motor|brancher)\.[0-9]+\.(name|species|site_spacing|step_size|filament_type))$)");
  for (const std::string& o : overrides) {
    const std::string key = o.substr(0, o.find('='));
    if (std::regex_match(key, frozen))
      throw InputError(fmt::format("--resume: --set {}: the stored state was built from this key (initial shape, "
                                   "copies, lattice or random streams), so a resumed run cannot change it",
                                   key));
  }
}

// Rates or diffusion constants so large that one window would take hours: refused before
// anything is written (the engine refuses the same at every window, with a RunError).
void checkChemistryLoad(const System& system, const Config& config) {
  if (!system.chemistry()) return;
  try {
    system.chemistry()->checkLoad(config.simulation.chemistry_window);
  } catch (const RunError& e) {
    throw InputError(fmt::format("{}: {}", config.source, e.what()));
  }
}

// The run's name: what makes it (its first effective config, seed, version).
std::string runId(const std::string& effective_toml) {
  return fmt::format("{:016x}", fnv1a64(std::string(CORTEX_VERSION) + "\n" + effective_toml));
}

// A resumed run continues the stored one: overrides may extend or change physics, but not
// what the stored state was built on (its windows, grid, random streams).
void checkResumable(const Config& stored, const Config& now, double checkpoint_time) {
  auto refuse = [](const std::string& key, const std::string& why) {
    throw InputError(fmt::format("--resume: {} cannot change when resuming: {}", key, why));
  };
  if (now.simulation.chemistry_window != stored.simulation.chemistry_window)
    refuse("simulation.chemistry_window", "window times are counted from the start of the run");
  if (now.simulation.seed != stored.simulation.seed) refuse("simulation.seed", "the random streams continue");
  if (now.simulation.end_time < checkpoint_time)
    throw InputError(fmt::format("--resume: simulation.end_time = {:g} s is before the checkpoint's t = {:g} s; a "
                                 "resume may keep end_time or extend it, not shorten the run past its checkpoint",
                                 now.simulation.end_time, checkpoint_time));
  if (now.chemistry.has_value() != stored.chemistry.has_value()) refuse("[[species]]", "the chemistry state is stored");
  if (now.chemistry) {
    const CompartmentGrid &a = now.chemistry->grid, &b = stored.chemistry->grid;
    if (a.size != b.size || a.shape != b.shape) refuse("[compartments]", "copies are stored per compartment");
    if (now.chemistry->engine != stored.chemistry->engine) refuse("chemistry.engine", "engines keep different state");
  }
}

// A checkpoint's clock against its own config (its snapshot count is checked against the
// snapshot files: TrajectoryWriter::checkResumable). Its checksum guards against damage
// only: an edited count of windows ran a 0.5 s run to t = 0.25 s and reported it finished
// (exit 0).
void checkCheckpointClock(const Config& stored, const SystemState& s, const std::filesystem::path& file) {
  const SimulationConfig& sim = stored.simulation;
  if (s.step < 0 || s.step > Simulation::windowsOf(sim) || !(s.time == Simulation::timeOfWindow(sim, s.step)))
    throw InputError(fmt::format("{}: its clock disagrees with its config ({} windows of {:g} s completed, yet "
                                 "t = {:g} s): edited or damaged; start again with --overwrite",
                                 file.string(), s.step, sim.chemistry_window, s.time));
}

// The work since t = 0 and where its time went; `wall` is this session's, which after a
// resume is less than those times, so the line says so.
void logThroughput(const System& system, double wall, bool resumed) {
  const RunCounters& c = system.counters;
  const std::int64_t evals = system.forceField().forceEvaluations();
  const double per_s = c.mechanics_seconds > 0 ? evals / c.mechanics_seconds : 0.0;
  if (!system.membranes().empty()) {
    std::string preconditioner;
    if (c.preconditioner_factorizations > 0)
      preconditioner = fmt::format(", Sobolev preconditioner {:.2f} s ({} factorizations)", c.preconditioner_seconds,
                                   c.preconditioner_factorizations);
    spdlog::info("mechanics: {} minimizations, {} iterations, {} force evaluations in {:.2f} s ({:.0f} per s); "
                 "of which forces {:.2f} s ({:.3g} vertex-gradient evaluations/s){}; remeshing {:.2f} s; wall {:.2f} s{}",
                 c.minimizations, c.minimizer_iterations, evals, c.mechanics_seconds, per_s, c.force_seconds,
                 c.force_seconds > 0 ? evals * static_cast<double>(system.numVertices()) / c.force_seconds : 0.0,
                 preconditioner, c.remesh_seconds, wall,
                 resumed ? " this session (the counts and times before it are since t = 0)" : "");
  }
  if (const FilamentNetwork* net = system.filaments())
    spdlog::info("filaments: {} beads; {} minimizations, {} force evaluations in {:.2f} s ({:.0f} force "
                 "evaluations/s); force-dependent rates and binding-pair search {:.2f} s",
                 net->numBeads(), c.minimizations, evals, c.mechanics_seconds, per_s, c.feedback_seconds);
  if (const ChemistryEngine* chem = system.chemistry())
    spdlog::info("chemistry: {} events ({} diffusion hops) in {:.2f} s ({:.3g} events/s)", chem->events(),
                 chem->diffusionEvents(), c.chemistry_seconds,
                 c.chemistry_seconds > 0 ? chem->events() / c.chemistry_seconds : 0.0);
  if (c.unconverged_minimizations > 0)
    spdlog::warn("{} of {} minimizations stopped before reaching the force tolerance",
                 c.unconverged_minimizations, c.minimizations);
}

// The checks a System makes as it is built (meshes, slicing, placement, regions) name
// the key but not the file: their errors get the config's name in front, like the
// reader's own.
std::unique_ptr<System> buildSystem(const Config& config, const SystemState* restored = nullptr) {
  try {
    return std::make_unique<System>(config, restored);
  } catch (const InputError& e) {
    const std::string what = e.what();
    if (config.source.empty() || what.rfind(config.source, 0) == 0) throw;
    throw InputError(config.source + ": " + what);
  }
}

}  // namespace

RunOutcome runSimulation(const RunRequest& request) {
  const auto start = std::chrono::steady_clock::now();
  // From the start: a SIGTERM during a long set-up stops the run after its first window
  // and checkpoint (exit 3), as documented, instead of killing it.
  const StopSignals stop;
  omp_set_num_threads(std::max(1, request.threads));
  // Eigen's dense products would otherwise split their sums over the OpenMP threads, and
  // results would change in the last digits with --threads (cortex parallelizes its own
  // loops in a fixed order instead).
  Eigen::setNbThreads(1);
  const auto setup_log = logTheSetUp();
  const bool resume = !request.resume_dir.empty();
  std::vector<std::string> overrides = request.overrides;
  if (request.seed) overrides.push_back(fmt::format("simulation.seed={}", *request.seed));

  std::optional<Checkpoint> checkpoint;
  Config config;
  std::filesystem::path outdir;
  CheckpointHeader header;
  if (resume) {
    outdir = request.resume_dir;
    if (!request.output_dir.empty())
      throw InputError("--resume continues in its own folder; -o cannot be combined with it");
    if (request.overwrite) throw InputError("--resume continues a run; --overwrite cannot be combined with it");
    refuseFrozenOverrides(overrides);
    checkpoint = readCheckpoint(outdir / "checkpoint.h5");
    header = checkpoint->header;
    // Errors name the stored config (its line numbers are the stored text's, not the file's).
    const std::string source = fmt::format("{} (the config stored in {})", header.config_source,
                                           (outdir / "checkpoint.h5").string());
    config = parseConfig(header.config_toml, source, header.base_dir, overrides);
    const Config stored = parseConfig(header.config_toml, source, header.base_dir, {});
    checkCheckpointClock(stored, checkpoint->state, outdir / "checkpoint.h5");
    checkResumable(stored, config, checkpoint->state.time);
    // trajectory.h5 carries the run's id: resuming checks that checkpoint and snapshots
    // are one run's before appending to them.
    if (!std::filesystem::exists(outdir / "trajectory.h5"))
      throw InputError(fmt::format("{}: trajectory.h5 is missing (deleted or moved?), and without it resume cannot "
                                   "tell whether checkpoint.h5 and the snapshots are one run's; restore it, or start "
                                   "again with --overwrite",
                                   outdir.string()));
    const std::string trajectory_run = trajectoryRunId(outdir);
    if (trajectory_run.empty())
      throw InputError(fmt::format("{}: trajectory.h5 cannot be read (damaged?); cannot resume", outdir.string()));
    if (trajectory_run != header.run_id)
      throw InputError(fmt::format("{}: checkpoint.h5 belongs to another run than trajectory.h5 (a checkpoint "
                                   "copied in?); cannot resume",
                                   outdir.string()));
  } else {
    config = loadConfig(request.config, overrides);
    outdir = request.output_dir.empty() ? std::filesystem::path(request.config.stem().string() + "_out")
                                        : request.output_dir;
    header.config_source = request.config.string();
    header.base_dir = request.config.parent_path().string();
    header.run_id = runId(config.effective_toml);
  }
  header.config_toml = config.effective_toml;
  // Everything that can refuse the input comes before anything is written.
  auto system = buildSystem(config, checkpoint ? &checkpoint->state : nullptr);
  checkChemistryLoad(*system, config);
  for (const char* name : kRunFiles) refuseForeignEntry(outdir, name);
  if (resume)
    TrajectoryWriter::checkResumable(outdir, header.next_snapshot, header.run_id, checkpoint->state.time);
  else
    prepareOutputFolder(outdir, request.overwrite);

  setUpLogging(outdir, resume, *setup_log);
  spdlog::info("cortex {} {} {} (seed {}, {} thread{})", CORTEX_VERSION, resume ? "resuming" : "running",
               resume ? outdir.string() : request.config.string(), config.simulation.seed, request.threads,
               request.threads == 1 ? "" : "s");
  for (const auto& m : system->membranes())
    spdlog::info("membrane \"{}\": {} vertices, {} triangles, {}", m->name(), m->mesh().numVertices(),
                 m->mesh().numFaces(), m->isClosed() ? "closed" : "open (boundary fixed)");

  TrajectoryWriter writer(outdir, resume ? header.next_snapshot : 0, resume, header.run_id, config.effective_toml);
  const bool live = !request.quiet && isatty(STDERR_FILENO);
  ProgressReporter progress(config.simulation.end_time, live, request.quiet ? 0.0 : request.progress_interval,
                            system->counters);
  OutputObserver observer(outdir, header, writer, progress, &stop,
                          {config.simulation.seed, request.threads, 0.0});
  Simulation simulation(*system, config.simulation, config.mechanics, observer);
  RunOutcome outcome;
  try {
    outcome = simulation.run(!resume);
  } catch (const RunStopped& e) {
    // Nothing of the abandoned window is written: the files end at the last window done.
    progress.finish();
    writer.flush();
    const double kept = observer.lastCheckpointTime();
    const std::string status =
        kept >= 0 ? fmt::format("its checkpoint of t = {:.6g} s is kept; continue with cortex run --resume {}", kept,
                                outdir.string())
        : resume ? fmt::format("the checkpoint it resumed from is kept; continue with cortex run --resume {}",
                               outdir.string())
                 : "no checkpoint was written yet, so there is nothing to resume: start it again with --overwrite";
    spdlog::warn("stopped by signal {} during window {} ({} completed): {}; {}", stop.signal(), system->step + 1,
                 system->step, e.what(), status);
    return RunOutcome::kStopped;
  } catch (const RunError& e) {
    progress.finish();
    try {
      writer.flush();  // the index lists every snapshot written
    } catch (const RunError& io) {
      spdlog::warn("the trajectory index could not be brought up to date: {}", io.what());
    }
    const double kept = observer.lastCheckpointTime();
    const std::string status =
        kept >= 0 ? fmt::format("the snapshots so far and the checkpoint of t = {:.6g} s are kept; fix the cause and "
                                "continue with --resume {}",
                                kept, outdir.string())
        : resume ? "the snapshots and checkpoint it resumed from are kept"
                 : "no checkpoint was written";
    spdlog::error("run failed at t = {:.6g} s ({} window{} completed): {}; {}", system->time(), system->step,
                  system->step == 1 ? "" : "s", e.what(), status);
    throw RunError(fmt::format("{} ({})", e.what(), status));
  }
  progress.finish();
  writer.flush();
  if (outcome == RunOutcome::kStopped) {
    spdlog::warn("stopped by signal {} at t = {:.6g} s ({} window{} completed) after writing a checkpoint; continue "
                 "with cortex run --resume {}",
                 stop.signal(), system->time(), system->step, system->step == 1 ? "" : "s", outdir.string());
    return outcome;
  }

  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  writeJsonAtomically(outdir / "summary.json",
                      summarize(*system, {config.simulation.seed, request.threads, wall}));
  logThroughput(*system, wall, resume);
  spdlog::info("finished at t = {:.6g} s in {:.2f} s wall; output in {}", system->time(), wall, outdir.string());
  // The one line a batch job's output always ends with: where the results are.
  fmt::print("cortex: finished t = {:.6g} s in {:.1f} s wall; results in {} (summary.json, observables.csv, "
             "trajectory.xdmf for ParaView)\n",
             system->time(), wall, outdir.string());
  std::fflush(stdout);
  return outcome;
}

std::string checkConfig(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  return checkLoadedConfig(loadConfig(file, overrides), file);
}

std::string checkLoadedConfig(const Config& config, const std::filesystem::path& file) {
  // Everything a run builds before its first step (meshes, filament placement, engines)
  // is built here too, so that check and run refuse the same inputs.
  const auto system = buildSystem(config);
  checkChemistryLoad(*system, config);
  const std::string chemistry =
      system->chemistry() ? fmt::format(", {} species, {} reactions in {} compartments",
                                        system->chemistryModel().species.size(),
                                        system->chemistryModel().reactions.size(), system->grid().count())
                          : "";
  const std::string filaments =
      system->filaments() ? fmt::format(", {} filaments", system->filaments()->filaments().size()) : "";
  return fmt::format("{}: ok ({} membrane{}, {} vertices{}{}, end_time {:g} s)", file.string(), config.membranes.size(),
                     config.membranes.size() == 1 ? "" : "s", system->numVertices(), filaments, chemistry,
                     config.simulation.end_time);
}

}  // namespace cortex
