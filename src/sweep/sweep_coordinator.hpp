// The one process that knows the whole sweep (the sweep itself, or MPI rank 0): reads
// and checks the sweep file, decides per member whether to skip, resume or start it,
// hands tasks out to an executor as slots free up, and writes the table at the end.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "sweep/member_check.hpp"
#include "sweep/member_executor.hpp"
#include "sweep/sweep_spec.hpp"

namespace cortex {

struct SweepRequest {
  std::filesystem::path file;        // the sweep file
  std::filesystem::path output_dir;  // default <sweep file stem>_out
  std::optional<int> parallel;       // local member processes at once; overrides the file's `parallel`
  int threads = 1;                   // OpenMP threads per member
  bool dry_run = false;              // check and list the members, run nothing
  bool quiet = false;                // no progress lines on the terminal
};

class SweepCoordinator {
 public:
  // Reads the sweep file and checks every member's config; throws InputError.
  explicit SweepCoordinator(SweepRequest request);

  // `--dry-run`: one line per member with its folder and overrides.
  std::string memberList() const;
  // Local member processes at once: --parallel, else the file's `parallel`, else one per
  // core (cores divided by --threads).
  std::size_t localSlots() const;
  // Runs the sweep on `executor` until every member ended or a stop signal; writes
  // sweep.csv and sweep.h5. Returns the exit code: 0 all ok, 1 some member failed, 3
  // stopped by a signal. Throws InputError (before any member starts) for an output
  // folder it cannot use or member folders of another sweep.
  int run(MemberExecutor& executor);

 private:
  SweepRequest request_;
  SweepSpec spec_;
  std::vector<CheckedMember> checked_;
};

}  // namespace cortex
