// The processes one drape command runs as: a process alone (started from a shell, a script, a
// Slurm batch script without srun), or the ranks of one MPI job (started by `mpirun -np N` or
// `srun`). MPI is initialised only in the second case, and only when a command first asks for the
// group (the task farm, a parallel fit): a plain `drape solve` never touches MPI, which is slow to
// start and can fail in containers. Whether a launcher started the process is read from the
// variables it sets (OMPI_COMM_WORLD_SIZE: Open MPI's mpirun; PMIX_RANK: PMIx, srun --mpi=pmix;
// PMI_RANK / PMI_SIZE: Slurm's PMI-2, MPICH's hydra).
//
// Under MPI, errors are returned, not fatal: a failed MPI call prints `drape: MPI error in
// <call>: <reason>` on stderr and aborts the whole job (MPI_Abort), so no rank waits forever for
// a rank that is gone; a rank that dies (a signal) makes the launcher end the job and say which.
#pragma once

namespace drape {

struct ProcessGroup {
  int rank = 0;  // this process, 0 … size − 1
  int size = 1;  // processes in the job; 1 when alone
  // Whether threads may compute beside the thread that talks to MPI (MPI_THREAD_FUNNELED given).
  bool threads_beside_mpi = true;
  bool IsCoordinator() const { return rank == 0; }  // the process that writes shared output
  bool IsDistributed() const { return size > 1; }
};

// True when drape was built with MPI (CMake found mpi-default-dev).
bool BuiltWithMpi();

// True when an MPI launcher started this process (the environment variables above).
bool StartedByMpiLauncher();

// This process's place in its job: {0, 1} when alone (or built without MPI: then a launcher's N
// processes each run alone, and one warning on stderr says so). The first call under a launcher
// initialises MPI (MPI_THREAD_FUNNELED: only the calling thread talks to MPI).
const ProcessGroup& Processes();

// Whether Processes() initialised MPI in this process (false for every process started alone).
bool MpiStarted();

// Waits (without spinning) until every rank gets here, then finalises MPI, if Processes()
// initialised it; otherwise does nothing. Safe to call more than once; main() calls it before it
// returns. Every rank must call it.
void FinishProcesses();

// For an error that ends this process's command early (an exception that reached the command's
// top): under MPI with several ranks the others may be waiting for this one in a collective call
// and would wait forever, so the whole job is aborted (MPI_Abort, exit status `status`);
// otherwise (alone, or MPI never started) does nothing.
void AbortJobAfterError(int status);

// Scoped FinishProcesses(), for main().
class ProcessGroupScope {
 public:
  ProcessGroupScope() = default;
  ProcessGroupScope(const ProcessGroupScope&) = delete;
  ProcessGroupScope& operator=(const ProcessGroupScope&) = delete;
  ~ProcessGroupScope() { FinishProcesses(); }
};

}  // namespace drape
