#include "io/run_driver.hpp"

#include <fmt/format.h>
#include <omp.h>
#include <spdlog/sinks/basic_file_sink.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <chrono>

#include "core/error.hpp"
#include "io/checkpoint.hpp"
#include "io/config.hpp"
#include "io/run_observer.hpp"
#include "io/summary.hpp"
#include "io/trajectory_writer.hpp"
#include "sim/simulation.hpp"

namespace cortex {
namespace {

void setUpLogging(const std::filesystem::path& outdir, bool append) {
  auto console = std::make_shared<spdlog::sinks::stderr_color_sink_mt>();
  console->set_pattern("%^%l%$: %v");
  console->set_level(spdlog::level::warn);
  auto file = std::make_shared<spdlog::sinks::basic_file_sink_mt>((outdir / "cortex.log").string(), !append);
  file->set_pattern("[%Y-%m-%d %H:%M:%S.%e] %l: %v");
  auto logger = std::make_shared<spdlog::logger>("cortex", spdlog::sinks_init_list{console, file});
  logger->set_level(spdlog::level::debug);
  logger->flush_on(spdlog::level::info);
  spdlog::set_default_logger(logger);
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
    refuse("simulation.end_time", fmt::format("the checkpoint is at t = {:g} s already", checkpoint_time));
  if (now.chemistry.has_value() != stored.chemistry.has_value()) refuse("[[species]]", "the chemistry state is stored");
  if (now.chemistry) {
    const CompartmentGrid &a = now.chemistry->grid, &b = stored.chemistry->grid;
    if (a.size != b.size || a.shape != b.shape) refuse("[compartments]", "copies are stored per compartment");
    if (now.chemistry->engine != stored.chemistry->engine) refuse("chemistry.engine", "engines keep different state");
  }
}

void logThroughput(const System& system, double wall) {
  const RunCounters& c = system.counters;
  const std::int64_t evals = system.forceField().forceEvaluations();
  const double per_s = c.mechanics_seconds > 0 ? evals / c.mechanics_seconds : 0.0;
  if (!system.membranes().empty())
    spdlog::info("mechanics: {} minimizations, {} iterations, {} force evaluations in {:.2f} s "
               "({:.0f} force evaluations/s, {:.3g} vertex-gradient evaluations/s); remeshing {:.2f} s; "
               "wall {:.2f} s",
               c.minimizations, c.minimizer_iterations, evals, c.mechanics_seconds, per_s,
               per_s * system.numVertices(), c.remesh_seconds, wall);
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

}  // namespace

void runSimulation(const RunRequest& request) {
  const auto start = std::chrono::steady_clock::now();
  omp_set_num_threads(std::max(1, request.threads));
  const bool resume = !request.resume_dir.empty();
  std::vector<std::string> overrides = request.overrides;
  if (request.seed) overrides.push_back(fmt::format("simulation.seed={}", *request.seed));

  std::optional<Checkpoint> checkpoint;
  Config config;
  std::filesystem::path outdir;
  CheckpointHeader header;
  if (resume) {
    outdir = request.resume_dir;
    checkpoint = readCheckpoint(outdir / "checkpoint.h5");
    header = checkpoint->header;
    config = parseConfig(header.config_toml, header.config_source, header.base_dir, overrides);
    checkResumable(parseConfig(header.config_toml, header.config_source, header.base_dir, {}), config,
                   checkpoint->state.time);
  } else {
    config = loadConfig(request.config, overrides);
    outdir = request.output_dir.empty() ? std::filesystem::path(request.config.stem().string() + "_out")
                                        : request.output_dir;
    header.config_source = request.config.string();
    header.base_dir = request.config.parent_path().string();
  }
  header.config_toml = config.effective_toml;
  std::error_code ec;
  std::filesystem::create_directories(outdir, ec);
  if (ec) throw InputError(fmt::format("{}: cannot create output folder: {}", outdir.string(), ec.message()));

  setUpLogging(outdir, resume);
  spdlog::info("cortex {} {} {} (seed {}, {} thread{})", CORTEX_VERSION, resume ? "resuming" : "running",
               resume ? outdir.string() : request.config.string(), config.simulation.seed, request.threads,
               request.threads == 1 ? "" : "s");

  auto system = std::make_unique<System>(config, checkpoint ? &checkpoint->state : nullptr);
  for (const auto& m : system->membranes())
    spdlog::info("membrane \"{}\": {} vertices, {} triangles, {}", m->name(), m->mesh().numVertices(),
                 m->mesh().numFaces(), m->isClosed() ? "closed" : "open (boundary fixed)");

  TrajectoryWriter writer(outdir, resume ? header.next_snapshot : 0, resume);
  const bool live = !request.quiet && isatty(STDERR_FILENO);
  OutputObserver observer(outdir, header, writer, config.simulation.end_time, live);
  Simulation simulation(*system, config.simulation, config.mechanics, observer);
  try {
    simulation.run(!resume);
  } catch (const RunError& e) {
    observer.finishProgress();
    spdlog::error("run failed at t = {:.6g} s (window {}): {}; the last snapshot and checkpoint are kept",
                  system->time(), system->step, e.what());
    throw;
  }
  observer.finishProgress();

  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  writeJsonAtomically(outdir / "summary.json",
                      summarize(*system, {config.simulation.seed, request.threads, wall}));
  logThroughput(*system, wall);
  spdlog::info("finished at t = {:.6g} s in {:.2f} s wall; output in {}", system->time(), wall, outdir.string());
}

std::string checkConfig(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  const Config config = loadConfig(file, overrides);
  // Everything a run builds before its first step (meshes, filament placement, engines)
  // is built here too, so that check and run refuse the same inputs.
  const auto system = std::make_unique<System>(config);
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
