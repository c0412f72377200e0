// A task farm: independent tasks, numbered, run by workers (MPI ranks or local threads) while one
// coordinator collects their results. `drape sweep` farms its variants (or warm-start chains) and
// `drape fit` its solves; neither knows how the work is spread.
//
// Contract:
// - `run(task)` is called exactly once per task, on some worker; it returns the task's result as
//   text (CSV rows, JSON, ...) and must not throw (a failed task is a result saying so).
// - `collect(task, result)` is called on the coordinator only, once per task, one call at a time,
//   in the order the tasks finish.
// - What a task computes must depend only on its number, never on which worker ran it or when:
//   that is what makes the results identical whatever the number of workers.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace drape {

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

TaskFarmSummary RunTaskFarm(const std::vector<int>& tasks, const TaskRunner& run,
                            const ResultCollector& collect, const TaskFarmOptions& options);

}  // namespace drape
