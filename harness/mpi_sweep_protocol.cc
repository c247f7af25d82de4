// The MPI sweep's messages: sending and receiving tagged bytes, the run index
// that prefixes a message about a run, and the spec broadcast to every rank.
#include <mpi.h>
#include <time.h>

#include <cstddef>
#include <exception>
#include <functional>
#include <memory>
#include <string>

#include "harness/mpi_sweep_internal.h"

namespace icp::detail {

double ThreadCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

bool Send(int dest, Tag tag, const std::string& bytes) {
  return MPI_Send(bytes.data(), static_cast<int>(bytes.size()), MPI_BYTE, dest, tag,
                  MPI_COMM_WORLD) == MPI_SUCCESS;
}

bool SendWhile(int dest, Tag tag, std::string bytes, const std::function<bool()>& keep_waiting) {
  // Owned here: a request given up on stays pending and may still read it.
  auto buffer = std::make_unique<std::string>(std::move(bytes));
  MPI_Request request;
  if (MPI_Isend(buffer->data(), static_cast<int>(buffer->size()), MPI_BYTE, dest, tag, MPI_COMM_WORLD,
                &request) != MPI_SUCCESS)
    return false;
  IdleBackoff backoff(std::chrono::milliseconds(10));
  while (true) {
    int done = 0;
    if (MPI_Test(&request, &done, MPI_STATUS_IGNORE) != MPI_SUCCESS) return false;
    if (done) return true;
    if (!keep_waiting()) {
      buffer.release();  // left to the pending request: the rank is about to end
      return false;
    }
    backoff.Sleep();
  }
}

bool TakeHeartbeat(int source) {
  int flag = 0;
  MPI_Status status;
  if (MPI_Iprobe(source, kHeartbeat, MPI_COMM_WORLD, &flag, &status) != MPI_SUCCESS || !flag) return false;
  MPI_Recv(nullptr, 0, MPI_BYTE, source, kHeartbeat, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return true;
}

bool TryReceive(int source, Message* m) {
  int flag = 0;
  MPI_Status status;
  if (MPI_Iprobe(source, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &status) != MPI_SUCCESS || !flag)
    return false;
  int count = 0;
  MPI_Get_count(&status, MPI_BYTE, &count);
  m->source = status.MPI_SOURCE;
  m->tag = status.MPI_TAG;
  m->bytes.resize(static_cast<std::size_t>(count));
  MPI_Recv(m->bytes.data(), count, MPI_BYTE, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD,
           MPI_STATUS_IGNORE);
  return true;
}

std::string WithIndex(std::size_t index, const std::string& rest) {
  return std::to_string(index) + "\n" + rest;
}

bool SplitIndex(const std::string& bytes, std::size_t* index, std::string* rest) {
  const std::size_t nl = bytes.find('\n');
  if (nl == std::string::npos || nl == 0) return false;
  try {
    *index = std::stoul(bytes.substr(0, nl));
  } catch (const std::exception&) {
    return false;
  }
  *rest = bytes.substr(nl + 1);
  return true;
}

void BroadcastSpec(int rank, std::string* text, std::string* error) {
  std::string packed = rank == 0 ? (error->empty() ? "T" + *text : "E" + *error) : "";
  long long size = static_cast<long long>(packed.size());
  MPI_Bcast(&size, 1, MPI_LONG_LONG, 0, MPI_COMM_WORLD);
  packed.resize(static_cast<std::size_t>(size));
  MPI_Bcast(packed.data(), static_cast<int>(size), MPI_BYTE, 0, MPI_COMM_WORLD);
  if (packed.empty()) packed = "E(no spec received)";
  (packed[0] == 'T' ? *text : *error) = packed.substr(1);
}

std::string RankName(int rank) { return "rank " + std::to_string(rank); }

}  // namespace icp::detail
