// `cortex sweep SWEEP.toml`: runs a sweep's members as local processes, or across MPI
// ranks when started by mpirun with more than one rank (docs/sweep.md).
#pragma once

#include "sweep/sweep_coordinator.hpp"

namespace cortex {

// Returns the exit code: 0 every member ok, 1 some member failed, 3 stopped by a signal
// (run again to continue). Throws InputError (exit code 2) for a bad sweep file, a bad
// member config or an unusable output folder, before any member runs. An MPI worker
// rank returns rank 0's exit code, 2 included, without a message of its own.
int runSweep(const SweepRequest& request);

}  // namespace cortex
