// A sweep across MPI ranks (`mpirun -n N cortex sweep ...`, built with MPI): rank 0
// checks the sweep, hands members out one at a time to whichever worker rank asks next
// (dynamic self-scheduling, so fast and slow members balance), collects the outcomes and
// writes the table; ranks 1..N-1 each run one member at a time as a child process. Rank
// 0 only dispatches: run N = (members at once) + 1 ranks. Every member folder must be
// reachable under the same path from every rank (a shared file system).
#pragma once

#include "sweep/sweep_coordinator.hpp"

namespace cortex {

#ifdef CORTEX_HAVE_MPI
// Initialises MPI, runs this rank's part, finalizes; every rank returns rank 0's exit
// code. Rank 0 throws InputError for bad input after releasing the workers.
int runSweepOnRanks(const SweepRequest& request);
#endif

}  // namespace cortex
