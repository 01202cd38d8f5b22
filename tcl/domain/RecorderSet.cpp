// SPDX-License-Identifier: MIT
#include "tcl/domain/RecorderSet.h"

#include "materials/InputError.h"

namespace dabs::domain {

int RecorderSet::add(std::unique_ptr<Recorder> recorder) {
  const int tag = nextTag_++;
  recorders_[tag] = std::move(recorder);
  return tag;
}

void RecorderSet::remove(int tag) {
  auto it = recorders_.find(tag);
  if (it == recorders_.end()) throw InputError("recorder", std::to_string(tag) + " does not exist");
  it->second->flush();
  recorders_.erase(it);
}

void RecorderSet::removeAll(bool resetTags) {
  flush();
  recorders_.clear();
  if (resetTags) nextTag_ = 0;
}

std::vector<int> RecorderSet::elementsRead() const {
  std::vector<int> tags;
  for (const auto& [tag, r] : recorders_) r->elementsRead(tags);
  return tags;
}

void RecorderSet::flush() {
  for (auto& [tag, r] : recorders_) r->flush();
}

void RecorderSet::record(const Domain& domain, const std::function<void()>& reactions) {
  bool reactionsDone = false;
  for (auto& [tag, r] : recorders_) {
    if (r->needsReactions() && !reactionsDone) {
      reactions();
      reactionsDone = true;
    }
    try {
      r->record(domain);
    } catch (const InputError& e) {
      if (!error_) error_ = "recorder " + std::to_string(tag) + ": " + e.what();
    }
  }
}

std::optional<std::string> RecorderSet::takeError() {
  std::optional<std::string> error;
  error.swap(error_);
  return error;
}

}  // namespace dabs::domain
