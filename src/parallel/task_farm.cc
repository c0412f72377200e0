#include "src/parallel/task_farm.h"

namespace drape {

// Serial farm: one worker, the coordinator itself.
TaskFarmSummary RunTaskFarm(const std::vector<int>& tasks, const TaskRunner& run,
                            const ResultCollector& collect, const TaskFarmOptions& /*options*/) {
  TaskFarmSummary summary;
  for (const int task : tasks) {
    collect(task, run(task));
    ++summary.tasks;
  }
  return summary;
}

}  // namespace drape
