#include <algorithm>
#include <thread>

#include "src/parallel/farm_backends.h"
#include "src/parallel/farm_queue.h"

namespace drape {
namespace {

TaskFarmSummary RunInOrder(const std::vector<int>& tasks, const TaskRunner& run,
                           const ResultCollector& collect) {
  TaskDispenser dispenser(static_cast<int>(tasks.size()));
  OutcomeCollector collector(tasks, collect, &dispenser);
  TaskFarmSummary summary;
  while (const auto index = dispenser.Take()) {
    collector.Take(RunOneTask(tasks, *index, run, 0));
    ++summary.tasks;
  }
  collector.ThrowIfFailed();
  return summary;
}

}  // namespace

TaskFarmSummary RunLocalFarm(const std::vector<int>& tasks, const TaskRunner& run,
                             const ResultCollector& collect, int threads) {
  threads = std::min(threads, static_cast<int>(tasks.size()));
  if (threads <= 1) return RunInOrder(tasks, run, collect);
  TaskDispenser dispenser(static_cast<int>(tasks.size()));
  OutcomeQueue queue;
  std::vector<std::thread> workers;
  workers.reserve(threads);
  for (int t = 0; t < threads; ++t) {
    workers.emplace_back(RunWorkerThread, std::cref(tasks), std::cref(run), &dispenser, &queue);
  }
  // Each worker's outcomes come before its `worker_done`: when every worker is done, every task
  // handed out has been collected (after a failure the dispenser hands out no more).
  OutcomeCollector collector(tasks, collect, &dispenser);
  TaskFarmSummary summary;
  summary.workers = threads;
  for (int running = threads; running > 0;) {
    const TaskOutcome outcome = *queue.Pop(-1);
    if (outcome.worker_done) {
      --running;
      continue;
    }
    collector.Take(outcome);
    ++summary.tasks;
  }
  for (auto& worker : workers) worker.join();
  collector.ThrowIfFailed();
  return summary;
}

}  // namespace drape
