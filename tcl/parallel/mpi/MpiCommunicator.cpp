// SPDX-License-Identifier: MIT
#include "tcl/parallel/mpi/MpiCommunicator.h"

#include <chrono>
#include <limits>
#include <stdexcept>
#include <thread>

namespace dabs::parallel {

namespace {

// Sleep between two polls of a wait: short against a message's use (a job, a model's exchange),
// long enough that a waiting process uses no measurable CPU.
constexpr auto kPoll = std::chrono::microseconds(200);

void check(int rc, const char* what) {
  if (rc != MPI_SUCCESS) throw std::runtime_error(std::string("MPI error in ") + what);
}

// Waits for a request without spinning.
void wait(MPI_Request& request) {
  for (;;) {
    int done = 0;
    check(MPI_Test(&request, &done, MPI_STATUS_IGNORE), "MPI_Test");
    if (done != 0) return;
    std::this_thread::sleep_for(kPoll);
  }
}

}  // namespace

MpiCommunicator::MpiCommunicator(MPI_Comm comm, bool owned, bool serviceThread)
    : comm_(comm), owned_(owned), serviceThread_(serviceThread) {
  check(MPI_Comm_rank(comm_, &rank_), "MPI_Comm_rank");
  check(MPI_Comm_size(comm_, &size_), "MPI_Comm_size");
}

MpiCommunicator::~MpiCommunicator() {
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (owned_ && finalized == 0) MPI_Comm_free(&comm_);
}

void MpiCommunicator::barrier() {
  MPI_Request request;
  check(MPI_Ibarrier(comm_, &request), "MPI_Ibarrier");
  wait(request);
}

void MpiCommunicator::send(int dest, int tag, std::string_view text) {
  if (text.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    throw std::length_error("message longer than 2^31 - 1 bytes");
  MPI_Request request;
  check(MPI_Isend(text.data(), static_cast<int>(text.size()), MPI_CHAR, dest, tag, comm_, &request),
        "MPI_Isend");
  wait(request);
}

Communicator::Message MpiCommunicator::take(const MPI_Status& probed) {
  int count = 0;
  check(MPI_Get_count(&probed, MPI_CHAR, &count), "MPI_Get_count");
  Message message;
  message.source = probed.MPI_SOURCE;
  message.text.resize(static_cast<std::size_t>(count));
  check(MPI_Recv(message.text.data(), count, MPI_CHAR, probed.MPI_SOURCE, probed.MPI_TAG, comm_,
                 MPI_STATUS_IGNORE),
        "MPI_Recv");
  return message;
}

Communicator::Message MpiCommunicator::receive(int source, int tag) {
  const int from = source == kAnySource ? MPI_ANY_SOURCE : source;
  for (;;) {
    int found = 0;
    MPI_Status status;
    check(MPI_Iprobe(from, tag, comm_, &found, &status), "MPI_Iprobe");
    if (found != 0) return take(status);
    std::this_thread::sleep_for(kPoll);
  }
}

std::optional<Communicator::Message> MpiCommunicator::tryReceive(int tag) {
  int found = 0;
  MPI_Status status;
  check(MPI_Iprobe(MPI_ANY_SOURCE, tag, comm_, &found, &status), "MPI_Iprobe");
  if (found == 0) return std::nullopt;
  return take(status);
}

std::string MpiCommunicator::broadcast(std::string text, int root) {
  long long length = static_cast<long long>(text.size());
  MPI_Request request;
  check(MPI_Ibcast(&length, 1, MPI_LONG_LONG, root, comm_, &request), "MPI_Ibcast");
  wait(request);
  if (length > std::numeric_limits<int>::max())
    throw std::length_error("message longer than 2^31 - 1 bytes");
  text.resize(static_cast<std::size_t>(length));
  check(MPI_Ibcast(text.data(), static_cast<int>(length), MPI_CHAR, root, comm_, &request),
        "MPI_Ibcast");
  wait(request);
  return text;
}

std::unique_ptr<Communicator> MpiCommunicator::duplicate() {
  MPI_Comm copy;
  check(MPI_Comm_dup(comm_, &copy), "MPI_Comm_dup");
  return std::make_unique<MpiCommunicator>(copy, true, serviceThread_);
}

}  // namespace dabs::parallel
