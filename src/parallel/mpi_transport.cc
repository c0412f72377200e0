#include "src/parallel/mpi_transport.h"

#ifdef DRAPE_WITH_MPI

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <numeric>
#include <thread>

namespace drape::mpi {

void Check(int code, const char* call) {
  if (code == MPI_SUCCESS) return;
  char reason[MPI_MAX_ERROR_STRING] = "";
  int length = 0;
  MPI_Error_string(code, reason, &length);
  std::fprintf(stderr, "drape: MPI error in %s: %s; aborting the job\n", call, reason);
  std::fflush(stderr);
  MPI_Abort(MPI_COMM_WORLD, 2);
}

void Backoff::Pause() {
  std::this_thread::sleep_for(std::chrono::microseconds(microseconds_));
  microseconds_ = std::min(2 * microseconds_, 500);
}

void Wait(MPI_Request* request) {
  Backoff backoff;
  for (;;) {
    int done = 0;
    Check(MPI_Test(request, &done, MPI_STATUS_IGNORE), "MPI_Test");
    if (done) return;
    backoff.Pause();
  }
}

MPI_Status Probe(int source, int tag) {
  Backoff backoff;
  for (;;) {
    int waiting = 0;
    MPI_Status status;
    Check(MPI_Iprobe(source, tag, MPI_COMM_WORLD, &waiting, &status), "MPI_Iprobe");
    if (waiting) return status;
    backoff.Pause();
  }
}

bool MessageWaiting(MPI_Status* status) {
  int waiting = 0;
  Check(MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &waiting, status), "MPI_Iprobe");
  return waiting != 0;
}

void SendInt(int value, int destination, int tag) {
  Check(MPI_Send(&value, 1, MPI_INT, destination, tag, MPI_COMM_WORLD), "MPI_Send");
}

int ReceiveInt(int source, int tag) {
  const MPI_Status status = Probe(source, tag);
  int value = 0;
  Check(MPI_Recv(&value, 1, MPI_INT, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD,
                 MPI_STATUS_IGNORE),
        "MPI_Recv");
  return value;
}

void SendText(const std::string& text, int destination, int tag) {
  // MPI_Send of a message this size returns once it is buffered or received; the receiver is
  // always polling for it, so the wait is short.
  Check(MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, destination, tag,
                 MPI_COMM_WORLD),
        "MPI_Send");
}

std::string ReceiveText(const MPI_Status& probed) {
  int count = 0;
  Check(MPI_Get_count(&probed, MPI_CHAR, &count), "MPI_Get_count");
  std::string text(static_cast<size_t>(count), '\0');
  Check(MPI_Recv(text.data(), count, MPI_CHAR, probed.MPI_SOURCE, probed.MPI_TAG, MPI_COMM_WORLD,
                 MPI_STATUS_IGNORE),
        "MPI_Recv");
  return text;
}

std::vector<std::string> AllGather(const std::string& mine) {
  int ranks = 1;
  Check(MPI_Comm_size(MPI_COMM_WORLD, &ranks), "MPI_Comm_size");
  int my_size = static_cast<int>(mine.size());
  std::vector<int> sizes(ranks), offsets(ranks);
  MPI_Request request;
  Check(MPI_Iallgather(&my_size, 1, MPI_INT, sizes.data(), 1, MPI_INT, MPI_COMM_WORLD, &request),
        "MPI_Iallgather");
  Wait(&request);
  std::exclusive_scan(sizes.begin(), sizes.end(), offsets.begin(), 0);
  std::string all(static_cast<size_t>(offsets.back() + sizes.back()), '\0');
  Check(MPI_Iallgatherv(mine.data(), my_size, MPI_CHAR, all.data(), sizes.data(), offsets.data(),
                        MPI_CHAR, MPI_COMM_WORLD, &request),
        "MPI_Iallgatherv");
  Wait(&request);
  std::vector<std::string> gathered;
  gathered.reserve(ranks);
  for (int r = 0; r < ranks; ++r) gathered.push_back(all.substr(offsets[r], sizes[r]));
  return gathered;
}

bool AnyRank(bool flag) {
  int mine = flag ? 1 : 0, any = 0;
  MPI_Request request;
  Check(MPI_Iallreduce(&mine, &any, 1, MPI_INT, MPI_LOR, MPI_COMM_WORLD, &request),
        "MPI_Iallreduce");
  Wait(&request);
  return any != 0;
}

}  // namespace drape::mpi

#endif  // DRAPE_WITH_MPI
