#include "src/parallel/task_farm.h"

#include <algorithm>
#include <thread>

#include "src/parallel/farm_backends.h"
#include "src/parallel/process_group.h"

namespace drape {

int EffectiveLocalThreads(int local_threads) {
  if (local_threads > 0) return local_threads;
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

TaskFarmSummary RunTaskFarm(const std::vector<int>& tasks, const TaskRunner& run,
                            const ResultCollector& collect, const TaskFarmOptions& options) {
  const ProcessGroup& group = Processes();
  if (group.IsDistributed()) return RunMpiFarm(tasks, run, collect, group);
  return RunLocalFarm(tasks, run, collect, EffectiveLocalThreads(options.local_threads));
}

}  // namespace drape
