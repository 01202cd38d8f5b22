// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string_view>

namespace dabs::analysis {

/// The automatic choice of how many threads update the elements (`threads auto`, the default):
/// measured on the model itself, not guessed from its size. The first steps of an analysis run
/// alternately on one thread and on every thread the process may use, in pairs of neighbouring
/// steps (their order swapped from pair to pair, so that a trend in the steps' cost falls on both
/// counts alike); each step's wall time per iteration is compared within its pair, and the
/// threads are kept when the median of the pairs' ratios says they save at least kMargin of the
/// time, else one thread. A trial that finds less than that gain but not a clear loss (a median
/// under kRecheckBelow) is run once more on the next steps, and the second decides: on a shared
/// machine a burst of another job's work in the first trial's steps read as no gain, or as a
/// loss of up to 31 %, on bridges where two threads save a third (6 of 50 runs at 10 and 30
/// spans, 2026-11-29). A second trial costs at most 10 steps on the slower count. Results are
/// bit-identical at any thread count (AnalysisModel::updateElements), so the trial changes
/// nothing but the time.
///
/// A choice is measured again after kRevisitAfter steps (a trial of pairs alone, with the same
/// rules): what the machine gives a second core changes over a run. Each revisit that confirms
/// the choice doubles the steps to the next (up to kRevisitAtMost); one that changes it starts
/// again from kRevisitAfter. On the 2-core machine of 2026-11-29 (03:48 UTC) the trial on the
/// 10-span bridge's early steps measured 1.12 to 1.26 in 3 of 7 runs, twice in a row, and kept
/// one thread for runs in which two threads gave 1.47 over one. A clear revisit runs 10 of its
/// 20 steps on the count not chosen: where two threads save a third, 10 one-thread steps cost
/// about 5 steps' time more in 420 (1.2 %); an unclear one (a second trial) twice that; less as
/// confirmations space the revisits out.
///
/// Why measured: on the machine of 2026-11-24 two threads paid at 10 and 30 spans of the case
/// study's bridge (1.5 times), not at 3 or 100 spans nor on a 2D RC frame of 16 elements (0.86),
/// and on the machine of 2026-11-29 at every size and on that frame (1.34 to 1.87): the share of
/// the time in element updates, the memory the fiber states stream through and what else runs on
/// the machine decide, and a size threshold gets at least one of them wrong.
class ThreadChoice {
 public:
  /// `available`: the threads the process may use (1: nothing to choose).
  explicit ThreadChoice(int available) noexcept;

  /// Forgets the measurements (a new model). `sharedWork`: the elements whose updates the threads
  /// would share; with fewer than two there is nothing to share (a pier pushover of one
  /// element), and one thread is chosen without a trial.
  void reset(std::size_t sharedWork = 2) noexcept;
  /// The thread count for the next step.
  int next() const noexcept;
  /// True while a choice is in force (after a trial, or for good with one thread available or
  /// nothing to share); false during a trial.
  bool decided() const noexcept { return decided_; }
  /// Records the step just run with next() threads: its wall time and its iterations. Call it
  /// after every converged step, decided or not: the steps since the choice count towards the
  /// next trial.
  void record(double seconds, int iterations) noexcept;
  /// True when there is nothing to choose (one thread available, or fewer than two elements to
  /// share): one thread for good, never measured.
  bool fixed() const noexcept { return fixed_; }
  /// The count chosen by the last decision (1 before the first).
  int chosen() const noexcept { return chosen_; }
  /// The count in force, for reports: the last decision's, also while a revisit alternates;
  /// before the first decision, the next step's.
  int inForce() const noexcept { return decisions_ > 0 ? chosen_ : next(); }
  /// Decisions made since reset() (the first trial's and each revisit's).
  int decisions() const noexcept { return decisions_; }
  /// True once a trial has measured (false with one thread available).
  bool measured() const noexcept { return measured_; }
  /// The threads' wall time per iteration over one thread's (the median of the last trial's
  /// pairs), once measured.
  double ratio() const noexcept { return ratio_; }

  /// Steps run on one thread before the trial (the first steps allocate and analyse patterns).
  static constexpr int kWarmUp = 2;
  /// Pairs of steps in the trial.
  static constexpr int kPairs = 10;
  /// The threads must save at least this share of a step's time (noise, and "never slower").
  static constexpr double kMargin = 0.05;
  /// A first trial's median below this (and above 1 - kMargin) is measured again.
  static constexpr double kRecheckBelow = 1.5;
  /// Trials at most in a row (a first and the one that follows an unclear answer).
  static constexpr int kTrials = 2;
  /// Steps run on a new choice before it is measured again.
  static constexpr int kRevisitAfter = 400;
  /// Most steps between revisits (after confirmations).
  static constexpr int kRevisitAtMost = 6400;
  /// Most threads a script or DABS_THREADS may ask for.
  static constexpr int kMaxThreads = 256;

  /// A thread count as `threads` and DABS_THREADS take it: a whole number from 1 to kMaxThreads,
  /// or `auto` (0); nothing for anything else.
  static std::optional<int> parseCount(std::string_view text) noexcept;

 private:
  int available_;
  bool decided_ = false;
  bool fixed_ = false;   ///< nothing to choose (one thread available, or nothing to share)
  int sinceChoice_ = 0;  ///< steps run on the choice in force
  int revisitAfter_ = kRevisitAfter;  ///< steps from the choice in force to its revisit
  int revisited_ = 0;                 ///< the choice a revisit trial measures (0: a first trial)
  int chosen_ = 1;
  int recorded_ = 0;   ///< the trial's steps so far, its warm-up counted (kWarmUp at a revisit)
  int trials_ = 0;     ///< trials in a row, since reset() or the start of a revisit
  int decisions_ = 0;  ///< decisions since reset() (the first trial's, each revisit's)
  bool measured_ = false;
  double ratio_ = 1.0;
  std::array<double, kPairs> one_{};
  std::array<double, kPairs> many_{};
};

}  // namespace dabs::analysis
