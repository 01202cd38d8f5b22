// SPDX-License-Identifier: MIT
#include "tcl/parallel/SerialCommunicator.h"

#include <stdexcept>
#include <string>

namespace dabs::parallel {

void SerialCommunicator::send(int dest, int /*tag*/, std::string_view /*text*/) {
  throw std::logic_error("one process only: no process " + std::to_string(dest) + " to send to");
}

Communicator::Message SerialCommunicator::receive(int source, int /*tag*/) {
  throw std::logic_error("one process only: no process " + std::to_string(source) +
                         " to receive from");
}

}  // namespace dabs::parallel
