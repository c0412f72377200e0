// The MPI calls of src/parallel/, checked and without busy waiting (only with DRAPE_WITH_MPI).
//
// Open MPI's blocking calls spin on the CPU while they wait; on a machine with as many ranks as
// cores (or more, oversubscribed) a waiting rank would take the core of a working one. So every
// wait here polls (MPI_Iprobe, MPI_Test) and sleeps between polls, from 20 µs doubling to 0.5 ms:
// a reply within a few µs is still seen at once, a long wait costs about 2,000 wake-ups a second
// (a few ms of CPU), and a reply is seen at most 0.5 ms late.
#pragma once

#ifdef DRAPE_WITH_MPI

#include <mpi.h>

#include <string>
#include <vector>

namespace drape::mpi {

// Aborts the job with `drape: MPI error in <call>: <reason>` if `code` is not MPI_SUCCESS.
void Check(int code, const char* call);

// Sleeps between polls, longer each time (reset by a new Backoff).
class Backoff {
 public:
  void Pause();

 private:
  int microseconds_ = 20;
};

// Waits for a request to complete, polling.
void Wait(MPI_Request* request);

// Waits for a message from `source` (or MPI_ANY_SOURCE) with `tag` (or MPI_ANY_TAG); its status.
MPI_Status Probe(int source, int tag);

// Whether a message is waiting (one poll, no wait); `status` describes it.
bool MessageWaiting(MPI_Status* status);

void SendInt(int value, int destination, int tag);
int ReceiveInt(int source, int tag);  // waits, polling
void SendText(const std::string& text, int destination, int tag);
std::string ReceiveText(const MPI_Status& probed);  // the message `probed` describes

// Every rank's `mine`, in rank order, on every rank (MPI_Allgatherv, polling).
std::vector<std::string> AllGather(const std::string& mine);

// True on every rank if `flag` is true on some rank (MPI_Allreduce, polling).
bool AnyRank(bool flag);

}  // namespace drape::mpi

#endif  // DRAPE_WITH_MPI
