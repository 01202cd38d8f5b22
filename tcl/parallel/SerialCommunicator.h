// SPDX-License-Identifier: MIT
#pragma once

#include "tcl/parallel/Communicator.h"

namespace dabs::parallel {

/// The serial program's communicator: one process, rank 0 of 1. A barrier and a broadcast return
/// at once; there is no other process to send to or receive from, so send and receive throw
/// std::logic_error (the commands check the process number before and report it).
class SerialCommunicator final : public Communicator {
 public:
  int rank() const override { return 0; }
  int size() const override { return 1; }
  void barrier() override {}
  void send(int dest, int tag, std::string_view text) override;
  Message receive(int source, int tag) override;
  std::optional<Message> tryReceive(int /*tag*/) override { return std::nullopt; }
  std::string broadcast(std::string text, int /*root*/) override { return text; }
  std::unique_ptr<Communicator> duplicate() override {
    return std::make_unique<SerialCommunicator>();
  }
  bool allowsServiceThread() const override { return true; }
};

}  // namespace dabs::parallel
