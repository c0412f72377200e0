// What a task of the task farm (src/parallel/task_farm.h) hands back to the coordinator, typed:
// the one encoding of every farmed command's results (`drape sweep`'s chains, the drops of
// `drape solve --drops`, `drape fabrics`' tasks) as the text the farm carries between threads and
// MPI ranks. Numbers cross as their bytes (src/parallel/byte_codec.h): read back bit for bit.
#pragma once

#include <string>
#include <vector>

namespace drape {

// One piece of work a farm task did: what became of it, its number, its row (a CSV line, as the
// command writes it to its table) and any numbers beside it (a drop's outline).
struct FarmRecord {
  std::string kind;  // solved, skipped, failed, unsaved, interrupted: the command's word
  int task = 0;
  std::string row;
  std::vector<double> numbers;

  bool operator==(const FarmRecord& other) const {
    return kind == other.kind && task == other.task && row == other.row && numbers == other.numbers;
  }
};

// A farm task's records as the farm's result text, and back. Decoding text that
// EncodeFarmRecords did not write is a programmer error (std::logic_error).
std::string EncodeFarmRecords(const std::vector<FarmRecord>& records);
std::vector<FarmRecord> DecodeFarmRecords(const std::string& text);

}  // namespace drape
