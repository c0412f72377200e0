// The two ways RunTaskFarm runs its tasks (src/parallel/task_farm.h). Internal to src/parallel/.
#pragma once

#include <vector>

#include "src/parallel/process_group.h"
#include "src/parallel/task_farm.h"

namespace drape {

// On `threads` threads of this process; the calling thread collects.
TaskFarmSummary RunLocalFarm(const std::vector<int>& tasks, const TaskRunner& run,
                             const ResultCollector& collect, int threads);

// Across the ranks of `group` (several): rank 0 coordinates (and works on a thread of its own),
// ranks > 0 work. Only with DRAPE_WITH_MPI.
TaskFarmSummary RunMpiFarm(const std::vector<int>& tasks, const TaskRunner& run,
                           const ResultCollector& collect, const ProcessGroup& group);

}  // namespace drape
