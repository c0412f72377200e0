// Work with fixed owners, every result given to every process: for a computation that all the
// ranks of an MPI job run in step (`drape fit`: every rank runs the same outer optimiser). Unit k
// is computed by one process only, its owner, which may keep state for it from one call to the
// next (a fit's equilibrium and its warm starts); the results come back on every process in unit
// order, so every process goes on with the same numbers, bit for bit.
//
// Each unit has an expected cost (e.g. its node count), which sets the owners once and for all
// (BalancedOwners: the costliest first, each to the least loaded rank), so they never depend on
// timing.
// - Several MPI ranks: each rank computes its own units, in unit order; then every rank's
//   results are gathered on every rank (MPI_Allgatherv). Every rank must call ComputeOnOwners
//   with the same `costs`, at the same point of its run.
// - Alone: the units run on `local_threads` threads, costliest first (any unit on any thread:
//   the process owns them all, so the caller's state per unit must not be shared between units).
//
// A unit that throws: alone, every unit still runs and then the exception of the lowest failed
// unit is rethrown as it was (an InputError stays one); under MPI every rank throws the same
// TaskFarmError ("task 2 failed on rank 1: …", the unit's number as the task's) after the
// exchange, so no rank is left waiting.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "src/parallel/process_group.h"

namespace drape {

using UnitComputation = std::function<std::string(int unit)>;

// Every unit's result, in unit order, on every process; unit k costs about costs[k].
std::vector<std::string> ComputeOnOwners(const std::vector<double>& costs,
                                         const UnitComputation& compute, int local_threads);

// The owning rank of each unit among `ranks`: units by decreasing cost (ties: the lower unit
// first), each to the rank with the least cost so far (ties: the lower rank).
std::vector<int> BalancedOwners(const std::vector<double>& costs, int ranks);

// The units by decreasing cost (ties: the lower unit first).
std::vector<int> CostliestFirst(const std::vector<double>& costs);

// True on every process if `flag` is true on some process (alone: `flag`). A collective call
// under MPI, like ComputeOnOwners.
bool AnyProcess(bool flag);

}  // namespace drape
