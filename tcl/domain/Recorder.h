// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

namespace dabs::domain {

class Domain;

/// Writes part of the state after each committed step. Files are written through RecorderFile:
/// rows reach the operating system as they are recorded, so nothing already recorded is lost when a
/// later step fails or the program is killed; flush() completes output that is written less often
/// (the viewer page) and is called at the end of every `analyze`, on `remove recorders`, `wipe` and
/// exit (Domain::flushRecorders).
class Recorder {
 public:
  virtual ~Recorder() = default;
  /// Records the domain's committed state at its current time; throws InputError when the output
  /// cannot be written.
  virtual void record(const Domain& domain) = 0;
  /// Writes buffered output to the file.
  virtual void flush() = 0;
  /// Called once with the domain before the first record (e.g. to resolve tags); may throw
  /// InputError for unknown tags.
  virtual void initialize(const Domain& /*domain*/) {}
  /// True when the recorder needs reactions computed before it records.
  virtual bool needsReactions() const { return false; }
  /// Appends the tags of the elements whose responses it records (the analysis keeps those
  /// up to date at every step; see AnalysisModel's sleeping pairs).
  virtual void elementsRead(std::vector<int>& /*tags*/) const {}
  /// Called when an eigen analysis finishes (recorders of eigenvectors write then).
  virtual void recordEigen(const Domain& /*domain*/) {}
};

}  // namespace dabs::domain
