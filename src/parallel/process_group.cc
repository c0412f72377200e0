#include "src/parallel/process_group.h"

#include <cstdio>
#include <cstdlib>
#include <initializer_list>

#include "src/parallel/mpi_transport.h"

namespace drape {
namespace {

bool mpi_started = false;
bool mpi_finished = false;

ProcessGroup StartGroup() {
  ProcessGroup group;
  if (!StartedByMpiLauncher()) return group;
#ifdef DRAPE_WITH_MPI
  int provided = MPI_THREAD_SINGLE;
  mpi::Check(MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided), "MPI_Init_thread");
  mpi_started = true;
  group.threads_beside_mpi = provided >= MPI_THREAD_FUNNELED;
  mpi::Check(MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN), "MPI_Comm_set_errhandler");
  mpi::Check(MPI_Comm_rank(MPI_COMM_WORLD, &group.rank), "MPI_Comm_rank");
  mpi::Check(MPI_Comm_size(MPI_COMM_WORLD, &group.size), "MPI_Comm_size");
#else
  std::fprintf(stderr,
               "drape: started by an MPI launcher, but this drape was built without MPI: each "
               "process runs the whole command alone\n");
#endif
  return group;
}

}  // namespace

bool BuiltWithMpi() {
#ifdef DRAPE_WITH_MPI
  return true;
#else
  return false;
#endif
}

bool StartedByMpiLauncher() {
  for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"}) {
    if (std::getenv(variable) != nullptr) return true;
  }
  return false;
}

const ProcessGroup& Processes() {
  static const ProcessGroup group = StartGroup();
  return group;
}

bool MpiStarted() { return mpi_started; }

void AbortJobAfterError(int status) {
  if (!mpi_started || mpi_finished || !Processes().IsDistributed()) return;
#ifdef DRAPE_WITH_MPI
  std::fflush(stdout);
  std::fflush(stderr);
  MPI_Abort(MPI_COMM_WORLD, status);
#else
  (void)status;
#endif
}

void FinishProcesses() {
  if (!mpi_started || mpi_finished) return;
  mpi_finished = true;
#ifdef DRAPE_WITH_MPI
  // A rank that finished early waits here for the others without spinning (MPI_Finalize would).
  MPI_Request barrier;
  mpi::Check(MPI_Ibarrier(MPI_COMM_WORLD, &barrier), "MPI_Ibarrier");
  mpi::Wait(&barrier);
  MPI_Finalize();
#endif
}

}  // namespace drape
