#include "src/parallel/shared_work.h"

#include <numeric>

#include "src/parallel/byte_codec.h"
#include "src/parallel/farm_backends.h"
#include "src/parallel/mpi_transport.h"
#include "src/parallel/task_farm.h"

namespace drape {
namespace {

std::vector<std::string> ComputeHere(int units, const UnitComputation& compute, int local_threads) {
  std::vector<int> indices(units);
  std::iota(indices.begin(), indices.end(), 0);
  std::vector<std::string> results(units);
  RunLocalFarm(
      indices, compute, [&](int unit, const std::string& result) { results[unit] = result; },
      EffectiveLocalThreads(local_threads));
  return results;
}

#ifdef DRAPE_WITH_MPI

// This rank's units, each as: unit, failed (0/1), result or failure message.
std::string ComputeMine(int units, const UnitComputation& compute, const ProcessGroup& group) {
  ByteWriter writer;
  for (int unit = group.rank; unit < units; unit += group.size) {
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

std::vector<std::string> ComputeAcrossRanks(int units, const UnitComputation& compute,
                                            const ProcessGroup& group) {
  const std::vector<std::string> gathered = mpi::AllGather(ComputeMine(units, compute, group));
  std::vector<std::string> results(units);
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

int OwnerRank(int unit, const ProcessGroup& group) { return unit % group.size; }

std::vector<std::string> ComputeOnOwners(int units, const UnitComputation& compute,
                                         int local_threads) {
  const ProcessGroup& group = Processes();
#ifdef DRAPE_WITH_MPI
  if (group.IsDistributed()) return ComputeAcrossRanks(units, compute, group);
#endif
  return ComputeHere(units, compute, local_threads);
}

bool AnyProcess(bool flag) {
#ifdef DRAPE_WITH_MPI
  if (Processes().IsDistributed()) return mpi::AnyRank(flag);
#endif
  return flag;
}

}  // namespace drape
