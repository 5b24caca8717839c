#include "sweep/sweep.hpp"

#include <cstdlib>
#include <iostream>
#include <string>

#include "core/error.hpp"
#include "sweep/mpi_sweep.hpp"
#include "sweep/member_process.hpp"

namespace cortex {
namespace {

// The number of processes an MPI launcher started (Open MPI's mpirun, MPICH's hydra); 1
// when not launched by one.
int launcherWorldSize() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
    if (const char* value = std::getenv(name)) return std::max(1, std::atoi(value));
  return 1;
}

}  // namespace

int runSweep(const SweepRequest& request) {
  // One rank needs no MPI: it runs its members as local processes like a plain sweep.
  if (launcherWorldSize() > 1) {
#ifdef CORTEX_HAVE_MPI
    return runSweepOnRanks(request);
#else
    throw InputError("cortex sweep was started by an MPI launcher, but this cortex was built without MPI "
                     "(install libopenmpi-dev and rebuild): every rank would run the whole sweep");
#endif
  }
  SweepCoordinator coordinator(request);
  if (request.dry_run) {
    std::cout << coordinator.memberList();
    return 0;
  }
  LocalExecutor local(currentExecutable(), coordinator.localSlots());
  return coordinator.run(local);
}

}  // namespace cortex
