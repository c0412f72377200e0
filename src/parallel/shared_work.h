// Work with fixed owners, every result given to every process: for a computation that all the
// ranks of an MPI job run in step (`drape fit`: every rank runs the same outer optimiser). Unit k
// is computed by one process only, its owner, which may keep state for it from one call to the
// next (a fit's equilibrium and its warm starts); the results come back on every process in unit
// order, so every process goes on with the same numbers, bit for bit.
//
// - Several MPI ranks: unit k belongs to rank k mod size, which computes its units in order;
//   then every rank's results are gathered on every rank (MPI_Allgatherv). Every rank must call
//   ComputeOnOwners with the same `units`, at the same point of its run.
// - Alone: the units run on `local_threads` threads (any unit on any thread: the process owns
//   them all, so the caller's state per unit must not be shared between units).
//
// A unit that throws: every process throws the same TaskFarmError ("task 2 failed on rank 1:
// …", the unit's number as the task's) after the exchange, so no rank is left waiting.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "src/parallel/process_group.h"

namespace drape {

using UnitComputation = std::function<std::string(int unit)>;

// Every unit's result, in unit order, on every process.
std::vector<std::string> ComputeOnOwners(int units, const UnitComputation& compute,
                                         int local_threads);

// The rank that computes `unit` (0 when alone).
int OwnerRank(int unit, const ProcessGroup& group);

// True on every process if `flag` is true on some process (alone: `flag`). A collective call
// under MPI, like ComputeOnOwners.
bool AnyProcess(bool flag);

}  // namespace drape
