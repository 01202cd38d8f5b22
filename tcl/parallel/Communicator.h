// SPDX-License-Identifier: MIT
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace dabs::parallel {

/// The processes of a run and the messages between them: MPI's world communicator in the MPI
/// program (dabs-mp), one process alone in the serial program. Messages are text (Tcl values).
/// Nothing here includes <mpi.h>; tcl/parallel/mpi implements it with MPI.
class Communicator {
 public:
  /// Source of `receive` meaning any process.
  static constexpr int kAnySource = -1;

  /// A message as received.
  struct Message {
    int source = 0;    ///< rank of the sender
    std::string text;  ///< the message
  };

  virtual ~Communicator() = default;
  /// This process's number, 0 ... size() - 1.
  virtual int rank() const = 0;
  /// Number of processes.
  virtual int size() const = 0;
  /// Returns when every process has called it.
  virtual void barrier() = 0;
  /// Sends `text` to process `dest` (not this one) under `tag`; returns once the text is handed
  /// over.
  virtual void send(int dest, int tag, std::string_view text) = 0;
  /// Waits for a message under `tag` from `source` (or kAnySource) and returns it.
  virtual Message receive(int source, int tag) = 0;
  /// A message under `tag` from any process if one has arrived, else nullopt (does not wait).
  virtual std::optional<Message> tryReceive(int tag) = 0;
  /// Process `root`'s `text`, on every process (collective: every process calls it).
  virtual std::string broadcast(std::string text, int root) = 0;
  /// A separate channel between the same processes (collective): its messages never meet this
  /// one's, so the job farm and a script's own send/recv cannot take each other's messages.
  virtual std::unique_ptr<Communicator> duplicate() = 0;
  /// Whether a second thread of this process may communicate while the first does not (MPI's
  /// MPI_THREAD_SERIALIZED): the job farm's dispatcher on process 0 needs it.
  virtual bool allowsServiceThread() const = 0;
};

}  // namespace dabs::parallel
