// A task farm: independent tasks, numbered, run by workers (MPI ranks or local threads) while one
// coordinator collects their results. `drape sweep` farms its variants (or warm-start chains) and
// `drape fit` its solves; neither knows how the work is spread.
//
// Contract:
// - `run(task)` is called exactly once per task, on some worker; it returns the task's result as
//   text (drape's commands: FarmRecords, src/parallel/farm_record.h) and must not throw (a failed
//   task is a result saying so).
// - `collect(task, result)` is called on the coordinator only, once per task, one call at a time,
//   in the order the tasks finish.
// - What a task computes must depend only on its number, never on which worker ran it or when:
//   that is what makes the results identical whatever the number of workers.
// - `run` may be called on several threads at once, and while `collect` runs (local threads, and
//   rank 0's own worker thread under MPI): it must not touch what another task or `collect`
//   writes.
//
// Where the tasks run (src/parallel/process_group.h says which case this process is in):
// - Alone (no MPI launcher, or `mpirun -np 1`): on `local_threads` threads of this process; the
//   calling thread collects (so `collect` is always called from the thread that called the farm).
//   With one thread, the tasks run in order on the calling thread.
// - Several MPI ranks: every rank calls RunTaskFarm with the same `tasks`. Rank 0 hands the tasks
//   out one at a time (the next to whichever rank returns a result first, so a long task does not
//   hold back the others), collects, and also runs tasks on one thread of its own (coordinating
//   costs little: it sleeps between polls; on 2 cores `mpirun -np 2` so has two workers, not one).
//   Ranks > 0 only run tasks, and return with `coordinator = false`: they must write no shared
//   output. `local_threads` is not used: start one rank per core.
//
// Failure policy: a task that throws anyway (a broken contract) is not retried; no further task is
// handed out, the tasks already running finish and their results are still collected, and then
// RunTaskFarm throws TaskFarmError ("task 7 failed on rank 2: …") on the coordinator; ranks > 0
// return normally. An exception from `collect` is handled the same way. A rank that dies ends the
// whole MPI job (the launcher reports it); an MPI error aborts it with a message.
#pragma once

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace drape {

// The help text of a command's `--threads` option, one owner for every command that farms.
inline constexpr const char* kLocalThreadsHelp =
    "worker threads when drape runs alone (not under mpirun/srun): 0 = the machine's cores, "
    "1 = one after another";

struct TaskFarmOptions {
  // Worker threads when the process is alone (not started by mpirun/srun with several ranks):
  // 0 = the machine's cores, 1 = serial.
  int local_threads = 0;
};

struct TaskFarmSummary {
  int tasks = 0;            // tasks run by the farm (all workers)
  int workers = 1;          // ranks or threads that ran tasks
  bool coordinator = true;  // false on MPI ranks other than 0: they write no shared output
};

using TaskRunner = std::function<std::string(int task)>;
using ResultCollector = std::function<void(int task, const std::string& result)>;

class TaskFarmError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

TaskFarmSummary RunTaskFarm(const std::vector<int>& tasks, const TaskRunner& run,
                            const ResultCollector& collect, const TaskFarmOptions& options);

// The threads `local_threads` means on this machine (0: the hardware's cores, at least 1).
int EffectiveLocalThreads(int local_threads);

}  // namespace drape
