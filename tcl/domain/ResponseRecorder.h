// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <vector>

#include "tcl/domain/Recorder.h"
#include "tcl/domain/RecorderFile.h"

namespace dabs::domain {

/// Output options shared by the Node, Element and Drift recorders.
struct RecorderOutput {
  std::string file;
  bool time = false;      ///< -time: first column is the time
  double deltaT = 0.0;    ///< -dT: record only when at least dT passed since the last record
  int precision = 6;      ///< -precision: significant digits (C++ stream default, like %g)
  bool envelope = false;  ///< Envelope recorders: min, max and max |value| rows, written at flush
};

/// A recorder writing one row of numbers per recorded step, OpenSees' layout: optional time, then
/// the values, separated by single spaces (OpenSees/OpenSees:SRC/handler/DataFileStream.cpp). Each
/// row reaches the operating system when it is recorded (at the commit of its step), so a killed
/// run keeps every committed step; envelope recorders rewrite their three rows when one changes.
/// A write error throws InputError.
class ResponseRecorder : public Recorder {
 public:
  /// Opens (truncates) the file; throws InputError when it cannot be written.
  explicit ResponseRecorder(RecorderOutput output);
  void record(const Domain& domain) override;
  void flush() override;

 protected:
  /// The values of one row for the domain's current state.
  virtual void values(const Domain& domain, std::vector<double>& out) = 0;
  /// Writes a row now (bypassing -dT), e.g. for eigenvectors.
  void writeRow(double time, const std::vector<double>& row);

 private:
  void appendNumber(double v);
  void writeEnvelope();
  RecorderOutput output_;
  RecorderFile file_;
  std::vector<double> row_;
  double nextTime_ = 0.0;
  bool anyRecord_ = false;
  // Envelope state: min, max, max |.| and the times they occurred.
  std::vector<double> min_, max_, absMax_, tMin_, tMax_, tAbs_;
};

}  // namespace dabs::domain
