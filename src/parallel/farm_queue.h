// The task farm's shared state inside one process: which task is handed out next, and the
// results that worker threads hand back to the collecting thread. Internal to src/parallel/.
#pragma once

#include <condition_variable>
#include <deque>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "src/parallel/task_farm.h"

namespace drape {

// Hands out the indices 0 … count − 1 once each, in order, to whichever worker asks; after Stop()
// (a failure) it hands out nothing more.
class TaskDispenser {
 public:
  explicit TaskDispenser(int count) : count_(count) {}
  std::optional<int> Take();
  void Stop();

 private:
  std::mutex mutex_;
  int next_ = 0;
  int count_ = 0;
};

// A task's outcome as a worker reports it: its result, or the reason it failed.
struct TaskOutcome {
  int index = 0;  // in the farm's task list
  bool failed = false;
  std::string text;          // the result, or the failure's message
  int rank = 0;              // the MPI rank that ran it (0 for threads)
  bool worker_done = false;  // not a task: the worker thread that pushed it takes no more tasks
};

// Runs `run(tasks[index])`, turning an exception into a failed outcome.
TaskOutcome RunOneTask(const std::vector<int>& tasks, int index, const TaskRunner& run, int rank);

// Outcomes from worker threads to the collecting thread.
class OutcomeQueue {
 public:
  void Push(TaskOutcome outcome);
  // The next outcome; waits for one (at most `wait_us` µs; 0: no wait, -1: until one comes).
  std::optional<TaskOutcome> Pop(int wait_us);

 private:
  std::mutex mutex_;
  std::condition_variable ready_;
  std::deque<TaskOutcome> outcomes_;
};

// A worker thread's loop: runs the tasks the dispenser hands out, pushes each outcome, then one
// `worker_done` outcome.
void RunWorkerThread(const std::vector<int>& tasks, const TaskRunner& run, TaskDispenser* dispenser,
                     OutcomeQueue* queue);

// Collects outcomes on the coordinator: calls `collect` for each result, remembers the first
// failure (a failed task, or an exception from `collect` itself) and stops the dispenser then, so
// that the farm drains what is running and ends.
class OutcomeCollector {
 public:
  OutcomeCollector(const std::vector<int>& tasks, const ResultCollector& collect,
                   TaskDispenser* dispenser)
      : tasks_(tasks), collect_(collect), dispenser_(dispenser) {}
  void Take(const TaskOutcome& outcome);
  // Throws TaskFarmError for the first failure, if any.
  void ThrowIfFailed() const;
  int collected() const { return collected_; }

 private:
  const std::vector<int>& tasks_;
  const ResultCollector& collect_;
  TaskDispenser* dispenser_;
  int collected_ = 0;
  std::optional<std::string> failure_;
};

}  // namespace drape
