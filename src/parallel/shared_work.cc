#include "src/parallel/shared_work.h"

#include <algorithm>
#include <exception>
#include <numeric>

#include "src/parallel/byte_codec.h"
#include "src/parallel/farm_backends.h"
#include "src/parallel/mpi_transport.h"
#include "src/parallel/task_farm.h"

namespace drape {
namespace {

// Alone, a unit's exception is kept as it is (an InputError stays one, out of memory stays
// std::bad_alloc): every unit runs, then the lowest failed unit's exception is rethrown.
std::vector<std::string> ComputeHere(const std::vector<double>& costs,
                                     const UnitComputation& compute, int local_threads) {
  std::vector<std::string> results(costs.size());
  std::vector<std::exception_ptr> failures(costs.size());
  const auto compute_keeping_failure = [&](int unit) {
    try {
      return compute(unit);
    } catch (...) {
      failures[unit] = std::current_exception();
      return std::string();
    }
  };
  RunLocalFarm(
      CostliestFirst(costs), compute_keeping_failure,
      [&](int unit, const std::string& result) { results[unit] = result; },
      EffectiveLocalThreads(local_threads));
  for (const auto& failure : failures) {
    if (failure) std::rethrow_exception(failure);
  }
  return results;
}

#ifdef DRAPE_WITH_MPI

// This rank's units, each as: unit, failed (0/1), result or failure message.
std::string ComputeMine(const std::vector<int>& owners, const UnitComputation& compute,
                        const ProcessGroup& group) {
  ByteWriter writer;
  for (int unit = 0; unit < static_cast<int>(owners.size()); ++unit) {
    if (owners[unit] != group.rank) continue;
    writer.Int(unit);
    try {
      const std::string result = compute(unit);
      writer.Int(0);
      writer.Text(result);
    } catch (const std::exception& error) {
      writer.Int(1);
      writer.Text(error.what());
    }
  }
  return writer.bytes();
}

std::vector<std::string> ComputeAcrossRanks(const std::vector<double>& costs,
                                            const UnitComputation& compute,
                                            const ProcessGroup& group) {
  const std::vector<std::string> gathered =
      mpi::AllGather(ComputeMine(BalancedOwners(costs, group.size), compute, group));
  std::vector<std::string> results(costs.size());
  std::string failure;
  for (size_t rank = 0; rank < gathered.size(); ++rank) {
    ByteReader reader(gathered[rank]);
    while (!reader.AtEnd()) {
      const int unit = static_cast<int>(reader.Int());
      const bool failed = reader.Int() != 0;
      results[unit] = reader.Text();
      if (failed && failure.empty()) {
        failure = "task " + std::to_string(unit) + " failed on rank " + std::to_string(rank) +
                  ": " + results[unit];
      }
    }
  }
  if (!failure.empty()) throw TaskFarmError(failure);
  return results;
}

#endif  // DRAPE_WITH_MPI

}  // namespace

std::vector<int> CostliestFirst(const std::vector<double>& costs) {
  std::vector<int> order(costs.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return costs[a] > costs[b]; });
  return order;
}

std::vector<int> BalancedOwners(const std::vector<double>& costs, int ranks) {
  std::vector<int> owners(costs.size(), 0);
  std::vector<double> load(ranks, 0.0);
  for (const int unit : CostliestFirst(costs)) {
    const int rank = static_cast<int>(std::min_element(load.begin(), load.end()) - load.begin());
    owners[unit] = rank;
    load[rank] += costs[unit];
  }
  return owners;
}

std::vector<std::string> ComputeOnOwners(const std::vector<double>& costs,
                                         const UnitComputation& compute, int local_threads) {
#ifdef DRAPE_WITH_MPI
  const ProcessGroup& group = Processes();
  if (group.IsDistributed()) return ComputeAcrossRanks(costs, compute, group);
#endif
  return ComputeHere(costs, compute, local_threads);
}

bool AnyProcess(bool flag) {
#ifdef DRAPE_WITH_MPI
  if (Processes().IsDistributed()) return mpi::AnyRank(flag);
#endif
  return flag;
}

}  // namespace drape
