#include "src/parallel/farm_queue.h"

#include <chrono>
#include <exception>
#include <utility>

namespace drape {

std::optional<int> TaskDispenser::Take() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (next_ >= count_) return std::nullopt;
  return next_++;
}

void TaskDispenser::Stop() {
  std::lock_guard<std::mutex> lock(mutex_);
  next_ = count_;
}

TaskOutcome RunOneTask(const std::vector<int>& tasks, int index, const TaskRunner& run, int rank) {
  TaskOutcome outcome;
  outcome.index = index;
  outcome.rank = rank;
  try {
    outcome.text = run(tasks[index]);
  } catch (const std::exception& error) {
    outcome.failed = true;
    outcome.text = error.what();
  } catch (...) {
    outcome.failed = true;
    outcome.text = "an exception that is not a std::exception";
  }
  return outcome;
}

void RunWorkerThread(const std::vector<int>& tasks, const TaskRunner& run, TaskDispenser* dispenser,
                     OutcomeQueue* queue) {
  while (const auto index = dispenser->Take()) queue->Push(RunOneTask(tasks, *index, run, 0));
  TaskOutcome done;
  done.worker_done = true;
  queue->Push(done);
}

void OutcomeQueue::Push(TaskOutcome outcome) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    outcomes_.push_back(std::move(outcome));
  }
  ready_.notify_one();
}

std::optional<TaskOutcome> OutcomeQueue::Pop(int wait_us) {
  std::unique_lock<std::mutex> lock(mutex_);
  const auto has_outcome = [this] { return !outcomes_.empty(); };
  if (wait_us < 0) {
    ready_.wait(lock, has_outcome);
  } else if (wait_us > 0) {
    ready_.wait_for(lock, std::chrono::microseconds(wait_us), has_outcome);
  }
  if (outcomes_.empty()) return std::nullopt;
  TaskOutcome outcome = std::move(outcomes_.front());
  outcomes_.pop_front();
  return outcome;
}

void OutcomeCollector::Take(const TaskOutcome& outcome) {
  const int task = tasks_[outcome.index];
  std::string failure;
  if (outcome.failed) {
    failure = "task " + std::to_string(task) + " failed" +
              (outcome.rank > 0 ? " on rank " + std::to_string(outcome.rank) : std::string()) +
              ": " + outcome.text;
  } else {
    try {
      collect_(task, outcome.text);
      ++collected_;
      return;
    } catch (const std::exception& error) {
      failure =
          "collecting the result of task " + std::to_string(task) + " failed: " + error.what();
    }
  }
  if (!failure_) failure_ = failure;
  dispenser_->Stop();
}

void OutcomeCollector::ThrowIfFailed() const {
  if (failure_) throw TaskFarmError(*failure_);
}

}  // namespace drape
