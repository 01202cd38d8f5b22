// SPDX-License-Identifier: MIT
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "tcl/domain/Recorder.h"

namespace dabs::domain {

/// The domain's recorders, tagged 0, 1, 2, ... in the order they were added (as OpenSees does),
/// with the first write error kept until asked for, so that a recorder that cannot write (a full
/// disk) does not stop the others.
class RecorderSet {
 public:
  /// Adds an initialised recorder and returns its tag.
  int add(std::unique_ptr<Recorder> recorder);
  /// Flushes and removes a recorder; throws InputError("recorder") when the tag is unknown.
  void remove(int tag);
  /// Flushes and removes every recorder; with `resetTags` the next one is tagged 0 again (wipe).
  void removeAll(bool resetTags);
  void flush();
  /// Records `domain` with every recorder; `reactions` is called once, before the first recorder
  /// that needs nodal reactions.
  void record(const Domain& domain, const std::function<void()>& reactions);
  /// Tags of the elements the recorders read (Recorder::elementsRead), unsorted.
  std::vector<int> elementsRead() const;
  /// The first write error since the last call, if any.
  std::optional<std::string> takeError();

 private:
  std::map<int, std::unique_ptr<Recorder>> recorders_;
  int nextTag_ = 0;
  std::optional<std::string> error_;
};

}  // namespace dabs::domain
