// The cortex command-line program: parses arguments and maps outcomes to exit codes
// (0 success, 1 failure during the run, 2 bad input, 3 stopped by a signal after a
// checkpoint).
#include <CLI/CLI.hpp>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <iostream>

#include "core/error.hpp"
#include "io/medyan_import.hpp"
#include "io/run_driver.hpp"
#include "sweep/member_check.hpp"
#include "sweep/sweep.hpp"

int main(int argc, char** argv) {
  // HDF5 locks files on open; a user looking at trajectory.h5 in h5py or ParaView
  // while the run goes on must not make the next snapshot fail.
  setenv("HDF5_USE_FILE_LOCKING", "FALSE", 0);

  CLI::App app{"cortex: simulator of the cell cortex (membranes, actin, chemistry)"};
  app.set_version_flag("--version", std::string("cortex ") + CORTEX_VERSION);
  app.require_subcommand(1);

  cortex::RunRequest run;
  std::string config;
  CLI::App* run_cmd = app.add_subcommand("run", "Run a simulation from a config file, or resume one");
  run_cmd->add_option("config", config, "Config file (TOML)");
  run_cmd->add_option("--resume", run.resume_dir, "Continue the run in OUTDIR from its checkpoint.h5");
  run_cmd->add_option("-o,--output", run.output_dir, "Output folder (default: <config name>_out)");
  std::string seed;  // parsed below: CLI11 would clamp an out-of-range integer silently
  run_cmd->add_option("--seed", seed, "Random seed (overrides simulation.seed)");
  run_cmd->add_option("--set", run.overrides, "Override a config key: key.path=value (repeatable)");
  run_cmd->add_option("--threads", run.threads, "OpenMP threads (results do not depend on it)")
      ->check(CLI::Range(1, 1024));
  run_cmd->add_flag("-q,--quiet", run.quiet, "No progress on stderr (the log still has it)");
  run_cmd->add_option("--progress", run.progress_interval,
                      "Seconds between progress lines when stderr is not a terminal (a batch job); 0: none")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  run_cmd->add_flag("--overwrite", run.overwrite, "Replace the results of an earlier run in the output folder");

  std::vector<std::string> check_overrides;
  CLI::App* check_cmd = app.add_subcommand("check", "Validate a config file without running it");
  check_cmd->add_option("config", config, "Config file (TOML)")->required();
  check_cmd->add_option("--set", check_overrides, "Override a config key: key.path=value");

  cortex::SweepRequest sweep;
  CLI::App* sweep_cmd = app.add_subcommand("sweep", "Run a parameter sweep: many runs of one config (docs/sweep.md)");
  sweep_cmd->add_option("sweep", sweep.file, "Sweep file (TOML)")->required();
  sweep_cmd->add_option("-o,--output", sweep.output_dir, "Output folder (default: <sweep name>_out)");
  sweep_cmd->add_option("--parallel", sweep.parallel, "Members at once (default: the file's parallel, else one per core)")
      ->check(CLI::Range(1, 4096));
  sweep_cmd->add_option("--threads", sweep.threads, "OpenMP threads per member")->check(CLI::Range(1, 1024));
  sweep_cmd->add_flag("--dry-run", sweep.dry_run, "Check every member and list them; run nothing");
  sweep_cmd->add_flag("-q,--quiet", sweep.quiet, "No progress lines on the terminal");

  std::string medyan_system, medyan_chemistry, medyan_output;
  bool medyan_overwrite = false;
  CLI::App* import_cmd = app.add_subcommand("import-medyan", "Translate MEDYAN input files into a config (docs/medyan.md)");
  import_cmd->add_option("system", medyan_system, "MEDYAN system input file")->required();
  import_cmd->add_option("chemistry", medyan_chemistry, "Chemistry input file (default: the system file's CHEMISTRYFILE)");
  import_cmd->add_option("-o,--output", medyan_output, "Config file to write (TOML)")->required();
  import_cmd->add_flag("--overwrite", medyan_overwrite, "Replace an existing output file");

  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return 2;
  }

  try {
    if (*import_cmd)
      return cortex::runImportMedyan(medyan_system,
                                     medyan_chemistry.empty() ? std::nullopt : std::optional(std::filesystem::path(medyan_chemistry)),
                                     medyan_output, medyan_overwrite, false);
    if (*check_cmd) {
      // Warnings to stderr: stdout carries the verdict alone, for scripts.
      spdlog::set_default_logger(spdlog::stderr_color_st("check"));
      if (cortex::isSweepFile(config)) {
        if (!check_overrides.empty()) {
          std::cerr << "cortex check: --set applies to a run config, not to a sweep file (" << config << ")\n";
          return 2;
        }
        std::cout << cortex::checkSweep(config) << '\n';
      } else {
        std::cout << cortex::checkConfig(config, check_overrides) << '\n';
      }
      return 0;
    }
    if (*sweep_cmd) return cortex::runSweep(sweep);
    if (config.empty() == run.resume_dir.empty()) {
      std::cerr << "cortex run: give either a config file or --resume OUTDIR\n";
      return 2;
    }
    run.config = config;
    if (!seed.empty()) {
      std::int64_t value = -1;
      const auto [end, error] = std::from_chars(seed.data(), seed.data() + seed.size(), value);
      if (error != std::errc() || end != seed.data() + seed.size() || value < 0) {
        std::cerr << "cortex: error: --seed: '" << seed << "' is not an integer in [0, 9223372036854775807]\n";
        return 2;
      }
      run.seed = value;
    }
    return cortex::runSimulation(run) == cortex::RunOutcome::kStopped ? 3 : 0;
  } catch (const cortex::InputError& e) {
    std::cerr << "cortex: error: " << e.what() << '\n';
    return 2;
  } catch (const cortex::RunError& e) {
    std::cerr << "cortex: run failed: " << e.what() << '\n';
    return 1;
  } catch (const std::bad_alloc&) {
    std::cerr << "cortex: run failed: out of memory (the model is too large for this machine: fewer compartments, "
                 "vertices or filaments)\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "cortex: internal error: " << e.what() << '\n';
    return 1;
  }
}
