// The task farm across MPI ranks (src/parallel/task_farm.h): rank 0 hands out task indices one at
// a time and collects; every rank runs tasks, rank 0 on a worker thread of its own.
//
// Messages (MPI_COMM_WORLD): rank 0 → worker, kTaskTag: one int, the task's index in `tasks`, or
// kNoMoreTasks; worker → rank 0, kResultTag or kFailureTag: the result's text, or the message of
// the exception the task threw. Rank 0 knows which index each rank holds.
#include <thread>

#include "src/parallel/farm_backends.h"
#include "src/parallel/farm_queue.h"
#include "src/parallel/mpi_transport.h"

namespace drape {

#ifdef DRAPE_WITH_MPI

namespace {

constexpr int kTaskTag = 1701;
constexpr int kResultTag = 1702;
constexpr int kFailureTag = 1703;
constexpr int kNoMoreTasks = -1;
constexpr int kPollMicroseconds = 200;  // the coordinator's wait for its thread between MPI polls

TaskFarmSummary WorkOnRank(const std::vector<int>& tasks, const TaskRunner& run,
                           const ProcessGroup& group) {
  for (;;) {
    const int index = mpi::ReceiveInt(0, kTaskTag);
    if (index == kNoMoreTasks) break;
    const TaskOutcome outcome = RunOneTask(tasks, index, run, group.rank);
    mpi::SendText(outcome.text, 0, outcome.failed ? kFailureTag : kResultTag);
  }
  TaskFarmSummary summary;
  summary.tasks = static_cast<int>(tasks.size());
  summary.workers = group.size;
  summary.coordinator = false;
  return summary;
}

class Coordinator {
 public:
  Coordinator(const std::vector<int>& tasks, const TaskRunner& run, const ResultCollector& collect,
              const ProcessGroup& group)
      : tasks_(tasks),
        run_(run),
        group_(group),
        dispenser_(static_cast<int>(tasks.size())),
        collector_(tasks, collect, &dispenser_),
        held_(group.size, kNoMoreTasks) {}

  TaskFarmSummary Run() {
    for (int rank = 1; rank < group_.size; ++rank) HandOut(rank);
    std::thread local;
    if (group_.threads_beside_mpi) {
      local_working_ = true;
      local =
          std::thread(RunWorkerThread, std::cref(tasks_), std::cref(run_), &dispenser_, &queue_);
    }
    while (busy_ranks_ > 0 || local_working_) Step();
    if (local.joinable()) local.join();
    collector_.ThrowIfFailed();
    TaskFarmSummary summary;
    summary.tasks = collected_;
    summary.workers = group_.size;
    return summary;
  }

 private:
  // One step: a rank's message if one waits, else the local thread's outcome (waiting for it up
  // to kPollMicroseconds while ranks are busy, so that their messages are seen that soon).
  void Step() {
    MPI_Status status;
    if (busy_ranks_ > 0 && mpi::MessageWaiting(&status)) {
      ReceiveFrom(status);
      return;
    }
    const auto outcome = queue_.Pop(busy_ranks_ > 0 ? kPollMicroseconds : -1);
    if (!outcome) return;
    if (outcome->worker_done) {
      local_working_ = false;
    } else {
      Collect(*outcome);
    }
  }

  void HandOut(int rank) {
    const auto index = dispenser_.Take();
    held_[rank] = index ? *index : kNoMoreTasks;
    mpi::SendInt(held_[rank], rank, kTaskTag);
    if (index) ++busy_ranks_;
  }

  void ReceiveFrom(const MPI_Status& status) {
    TaskOutcome outcome;
    outcome.rank = status.MPI_SOURCE;
    outcome.index = held_[outcome.rank];
    outcome.failed = status.MPI_TAG == kFailureTag;
    outcome.text = mpi::ReceiveText(status);
    --busy_ranks_;
    Collect(outcome);
    HandOut(outcome.rank);
  }

  void Collect(const TaskOutcome& outcome) {
    collector_.Take(outcome);
    ++collected_;
  }

  const std::vector<int>& tasks_;
  const TaskRunner& run_;
  const ProcessGroup& group_;
  TaskDispenser dispenser_;
  OutcomeQueue queue_;
  OutcomeCollector collector_;
  std::vector<int> held_;  // per rank: the index it is running, or kNoMoreTasks
  int busy_ranks_ = 0;
  bool local_working_ = false;
  int collected_ = 0;
};

}  // namespace

TaskFarmSummary RunMpiFarm(const std::vector<int>& tasks, const TaskRunner& run,
                           const ResultCollector& collect, const ProcessGroup& group) {
  if (!group.IsCoordinator()) return WorkOnRank(tasks, run, group);
  return Coordinator(tasks, run, collect, group).Run();
}

#else

TaskFarmSummary RunMpiFarm(const std::vector<int>& tasks, const TaskRunner& run,
                           const ResultCollector& collect, const ProcessGroup& /*group*/) {
  // Processes() reports a single process when drape is built without MPI.
  return RunLocalFarm(tasks, run, collect, 1);
}

#endif  // DRAPE_WITH_MPI

}  // namespace drape
