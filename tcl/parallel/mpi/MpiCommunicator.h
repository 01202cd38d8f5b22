// SPDX-License-Identifier: MIT
#pragma once

#include <mpi.h>

#include "tcl/parallel/Communicator.h"

namespace dabs::parallel {

/// Communicator over an MPI communicator (MPI_COMM_WORLD or a duplicate of it). Waiting is done
/// by polling with short sleeps instead of MPI's blocking calls, which spin at full speed in Open
/// MPI and would take the core a job on the same machine needs (two ranks on two cores).
class MpiCommunicator final : public Communicator {
 public:
  /// Uses `comm`; frees it at destruction when `owned` (a duplicate) and MPI is still running.
  /// `serviceThread`: MPI was started with at least MPI_THREAD_SERIALIZED.
  MpiCommunicator(MPI_Comm comm, bool owned, bool serviceThread);
  ~MpiCommunicator() override;
  MpiCommunicator(const MpiCommunicator&) = delete;
  MpiCommunicator& operator=(const MpiCommunicator&) = delete;

  int rank() const override { return rank_; }
  int size() const override { return size_; }
  void barrier() override;
  void send(int dest, int tag, std::string_view text) override;
  Message receive(int source, int tag) override;
  std::optional<Message> tryReceive(int tag) override;
  std::string broadcast(std::string text, int root) override;
  std::unique_ptr<Communicator> duplicate() override;
  bool allowsServiceThread() const override { return serviceThread_; }

 private:
  Message take(const MPI_Status& probed);

  MPI_Comm comm_;
  bool owned_;
  bool serviceThread_;
  int rank_ = 0;
  int size_ = 1;
};

}  // namespace dabs::parallel
