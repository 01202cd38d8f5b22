// SPDX-License-Identifier: MIT
// The automatic thread choice on made-up step times: the order of its trial (warm-up on one
// thread, then pairs of steps with the order swapped from pair to pair), the decision by the
// median of the pairs' time-per-iteration ratios against the margin, a second trial when the
// first gives no clear answer, the trials that measure a choice again after a while, and that a
// steady rise of the steps' cost (a model yielding more and more) does not pass for a gain of the
// threads.
#include "tcl/analysis/driver/ThreadChoice.h"

#include <gtest/gtest.h>

#include <vector>

namespace dabs::analysis {
namespace {

constexpr int kTrialSteps = ThreadChoice::kWarmUp + 2 * ThreadChoice::kPairs;

/// Runs steps [first, first + count) with a step time `time(threads, step)` per iteration (two
/// iterations a step) and returns the thread counts the choice asked for.
template <class Time>
std::vector<int> runSteps(ThreadChoice& choice, Time time, int first, int count) {
  std::vector<int> asked;
  for (int step = first; step < first + count; ++step) {
    const int n = choice.next();
    asked.push_back(n);
    choice.record(2.0 * time(n, step), 2);
  }
  return asked;
}

/// Step times (per iteration, by thread count): two threads 40 % faster, 60 % slower, or even.
const auto kGain = [](int n, int) { return n == 2 ? 0.6 : 1.0; };
const auto kLoss = [](int n, int) { return n == 2 ? 1.6 : 1.0; };
const auto kEven = [](int, int) { return 1.0; };

/// Steps of two iterations and equal times while the choice holds (at most kRevisitAtMost + 1),
/// each on the chosen count: how many ran before a revisit began.
int holdSteps(ThreadChoice& choice) {
  int held = 0;
  while (choice.decided() && held <= ThreadChoice::kRevisitAtMost) {
    EXPECT_EQ(choice.next(), choice.chosen());
    choice.record(2.0, 2);
    ++held;
  }
  return held;
}

/// The first trial: warm-up and pairs.
template <class Time>
std::vector<int> runTrial(ThreadChoice& choice, Time time) {
  return runSteps(choice, time, 0, kTrialSteps);
}

TEST(ThreadChoiceTest, OneAvailableThreadIsDecidedAtOnce) {
  ThreadChoice choice(1);
  EXPECT_TRUE(choice.decided());
  EXPECT_EQ(choice.next(), 1);
  choice.record(1.0, 1);
  EXPECT_FALSE(choice.measured());
}

// One element: nothing for threads to share, so one thread without a trial; two elements give the
// trial back.
TEST(ThreadChoiceTest, FewerThanTwoElementsAreDecidedAtOnce) {
  ThreadChoice choice(2);
  choice.reset(1);
  EXPECT_TRUE(choice.decided());
  EXPECT_EQ(choice.next(), 1);
  choice.record(1.0, 1);
  EXPECT_FALSE(choice.measured());
  choice.reset(2);
  EXPECT_FALSE(choice.decided());
}

TEST(ThreadChoiceTest, TrialWarmsUpOnOneThreadThenAlternatesInSwappedPairs) {
  ThreadChoice choice(2);
  const auto asked = runTrial(choice, kGain);
  const std::vector<int> expected{1, 1,                           // warm-up
                                  1, 2, 2, 1, 1, 2, 2, 1, 1, 2,   // pairs 0-4
                                  2, 1, 1, 2, 2, 1, 1, 2, 2, 1};  // pairs 5-9
  EXPECT_EQ(asked, expected);
  EXPECT_TRUE(choice.decided());
}

TEST(ThreadChoiceTest, KeepsTheThreadsWhenTheySaveMoreThanTheMargin) {
  ThreadChoice choice(2);
  runTrial(choice, kGain);
  ASSERT_TRUE(choice.measured());
  EXPECT_NEAR(choice.ratio(), 0.6, 1e-12);
  EXPECT_EQ(choice.next(), 2);
}

/// The second trial, after the first: its pairs alone (no warm-up).
template <class Time>
std::vector<int> runNextTrial(ThreadChoice& choice, Time time) {
  return runSteps(choice, time, kTrialSteps, 2 * ThreadChoice::kPairs);
}

// A gain within the margin is no clear answer: a second trial (pairs alone, in the same swapped
// order) measures again, and the same gain then keeps one thread.
TEST(ThreadChoiceTest, OneThreadWhenTheGainIsWithinTheMarginTwice) {
  ThreadChoice choice(2);
  const auto time = [](int n, int) { return n == 2 ? 0.97 : 1.0; };
  runTrial(choice, time);
  EXPECT_NEAR(choice.ratio(), 0.97, 1e-12);
  EXPECT_TRUE(choice.measured());
  EXPECT_FALSE(choice.decided());
  const auto asked = runNextTrial(choice, time);
  const std::vector<int> expected{1, 2, 2, 1, 1, 2, 2, 1, 1, 2, 2, 1, 1, 2, 2, 1, 1, 2, 2, 1};
  EXPECT_EQ(asked, expected);
  EXPECT_TRUE(choice.decided());
  EXPECT_NEAR(choice.ratio(), 0.97, 1e-12);
  EXPECT_EQ(choice.next(), 1);
}

// Another job's work during the first trial's two-thread steps hides a gain of 40 %: the second
// trial finds it and keeps the threads.
TEST(ThreadChoiceTest, ASecondTrialFindsTheGainANoisyFirstOneMissed) {
  ThreadChoice choice(2);
  runTrial(choice, [](int n, int) { return n == 2 ? 1.02 : 1.0; });
  ASSERT_FALSE(choice.decided());
  runNextTrial(choice, kGain);
  ASSERT_TRUE(choice.decided());
  EXPECT_NEAR(choice.ratio(), 0.6, 1e-12);
  EXPECT_EQ(choice.next(), 2);
}

// A clear loss (past kRecheckBelow, 1.5) decides at once; a gain past the margin too.
TEST(ThreadChoiceTest, AClearAnswerIsNotMeasuredAgain) {
  for (const double twoThreads : {1.6, 0.6}) {
    ThreadChoice choice(2);
    runTrial(choice, [&](int n, int) { return n == 2 ? twoThreads : 1.0; });
    EXPECT_TRUE(choice.decided()) << twoThreads;
  }
}

TEST(ThreadChoiceTest, OneThreadWhenTheThreadsAreSlower) {
  ThreadChoice choice(2);
  runTrial(choice, [](int n, int) { return n == 2 ? 1.2 : 1.0; });
  runNextTrial(choice, [](int n, int) { return n == 2 ? 1.2 : 1.0; });
  EXPECT_TRUE(choice.decided());
  EXPECT_EQ(choice.next(), 1);
}

// Every step costs 10 % more than the one before, whatever the threads: within a pair the second
// step is the dearer, and since the order swaps, the pairs' ratios are 1.1 and 1 / 1.1 in turn;
// their median is (1.1 + 1 / 1.1) / 2 = 1.0045, no gain. Without the swap it would read 1 / 1.1
// = 0.91 for the threads, past the margin.
TEST(ThreadChoiceTest, ASteadyRiseOfTheStepsCostIsNoGain) {
  ThreadChoice choice(2);
  const auto rise = [](int, int step) {
    double t = 1.0;
    for (int i = 0; i < step; ++i) t *= 1.1;
    return t;
  };
  runTrial(choice, rise);
  EXPECT_NEAR(choice.ratio(), 0.5 * (1.1 + 1.0 / 1.1), 1e-12);
  runNextTrial(choice, rise);  // no clear answer: measured again, the same
  EXPECT_TRUE(choice.decided());
  EXPECT_NEAR(choice.ratio(), 0.5 * (1.1 + 1.0 / 1.1), 1e-12);
  EXPECT_EQ(choice.next(), 1);
}

// A choice holds for kRevisitAfter steps and is then measured again (pairs alone, in the swapped
// order): the machine that gave the threads 40 % now gives them a clear loss, and the choice
// follows it; the next revisit finds the gain again.
TEST(ThreadChoiceTest, AChoiceIsMeasuredAgainAfterKRevisitAfterSteps) {
  ThreadChoice choice(2);
  runTrial(choice, kGain);
  ASSERT_EQ(choice.next(), 2);
  int step = kTrialSteps;
  const auto held = runSteps(choice, kLoss, step, ThreadChoice::kRevisitAfter);
  step += ThreadChoice::kRevisitAfter;
  EXPECT_EQ(held, std::vector<int>(ThreadChoice::kRevisitAfter, 2));
  EXPECT_FALSE(choice.decided());
  EXPECT_NEAR(choice.ratio(), 0.6, 1e-12);  // the last trial's until the new one ends
  const auto revisit = runSteps(choice, kLoss, step, 2 * ThreadChoice::kPairs);
  step += 2 * ThreadChoice::kPairs;
  const std::vector<int> pairs{1, 2, 2, 1, 1, 2, 2, 1, 1, 2, 2, 1, 1, 2, 2, 1, 1, 2, 2, 1};
  EXPECT_EQ(revisit, pairs);
  ASSERT_TRUE(choice.decided());
  EXPECT_NEAR(choice.ratio(), 1.6, 1e-12);
  EXPECT_EQ(choice.next(), 1);
  EXPECT_EQ(runSteps(choice, kGain, step, ThreadChoice::kRevisitAfter),
            std::vector<int>(ThreadChoice::kRevisitAfter, 1));
  step += ThreadChoice::kRevisitAfter;
  EXPECT_EQ(runSteps(choice, kGain, step, 2 * ThreadChoice::kPairs), pairs);
  EXPECT_NEAR(choice.ratio(), 0.6, 1e-12);
  EXPECT_EQ(choice.next(), 2);
}

// A revisit that confirms the choice doubles the steps to the next one (400, 800, 1600, up to
// 6400); one that changes the choice starts again from 400.
TEST(ThreadChoiceTest, ConfirmedChoicesAreRevisitedLessOften) {
  ThreadChoice choice(2);
  runTrial(choice, kGain);
  // Steps on the two threads chosen until the next trial starts, then that trial.
  auto stepsToRevisit = [&](auto time) {
    EXPECT_EQ(choice.chosen(), 2);
    const int held = holdSteps(choice);
    runSteps(choice, time, 0, 2 * ThreadChoice::kPairs);
    return held;
  };
  std::vector<int> intervals;
  for (int k = 0; k < 6; ++k) intervals.push_back(stepsToRevisit(kGain));
  EXPECT_EQ(intervals, (std::vector<int>{400, 800, 1600, 3200, 6400, 6400}));
  EXPECT_EQ(stepsToRevisit(kLoss), 6400);  // this revisit finds a loss: one thread
  ASSERT_EQ(choice.next(), 1);
  EXPECT_EQ(holdSteps(choice), ThreadChoice::kRevisitAfter);
}

// A revisit without a clear answer measures a second time, as a first trial does (40 steps in
// all), and a confirmation after the two still doubles the steps to the next revisit; a reset in
// the middle of a revisit starts over (a first trial, then 400 steps).
TEST(ThreadChoiceTest, AnUnclearRevisitMeasuresTwiceAndAResetStartsOver) {
  ThreadChoice choice(2);
  runTrial(choice, kGain);
  EXPECT_EQ(holdSteps(choice), ThreadChoice::kRevisitAfter);
  runSteps(choice, kEven, 0, 2 * ThreadChoice::kPairs);
  EXPECT_FALSE(choice.decided());  // no clear answer: a second trial
  EXPECT_EQ(choice.decisions(), 1);
  runSteps(choice, kGain, 0, 2 * ThreadChoice::kPairs);
  ASSERT_TRUE(choice.decided());
  EXPECT_EQ(choice.decisions(), 2);
  EXPECT_EQ(choice.next(), 2);
  EXPECT_EQ(holdSteps(choice), 2 * ThreadChoice::kRevisitAfter);
  runSteps(choice, kGain, 0, 4);  // into the revisit
  choice.reset();
  EXPECT_EQ(choice.decisions(), 0);
  runTrial(choice, kGain);
  EXPECT_EQ(holdSteps(choice), ThreadChoice::kRevisitAfter);
}

// With nothing to choose the choice is never measured, however long the run.
TEST(ThreadChoiceTest, NothingToChooseIsNeverMeasured) {
  ThreadChoice one(1);
  ThreadChoice single(2);
  single.reset(1);
  for (ThreadChoice* choice : {&one, &single}) {
    const auto asked = runSteps(
        *choice, [](int n, int) { return n == 2 ? 0.5 : 1.0; }, 0, 3 * ThreadChoice::kRevisitAfter);
    EXPECT_EQ(asked, std::vector<int>(3 * ThreadChoice::kRevisitAfter, 1));
    EXPECT_FALSE(choice->measured());
    EXPECT_TRUE(choice->decided());
  }
}

TEST(ThreadChoiceTest, ResetMeasuresAnew) {
  ThreadChoice choice(2);
  runTrial(choice, kGain);
  ASSERT_EQ(choice.next(), 2);
  choice.reset();
  EXPECT_FALSE(choice.decided());
  EXPECT_FALSE(choice.measured());
  EXPECT_EQ(choice.next(), 1);
  runTrial(choice, [](int n, int) { return n == 2 ? 1.8 : 1.0; });
  EXPECT_EQ(choice.next(), 1);
}

TEST(ThreadChoiceTest, ParsesACountFrom1To256OrAuto) {
  EXPECT_EQ(ThreadChoice::parseCount("auto"), 0);
  EXPECT_EQ(ThreadChoice::parseCount("1"), 1);
  EXPECT_EQ(ThreadChoice::parseCount("256"), 256);
  for (const char* bad : {"0", "257", "-2", "2.5", "2x", "", "Auto", " 2"})
    EXPECT_FALSE(ThreadChoice::parseCount(bad).has_value()) << '"' << bad << '"';
}

}  // namespace
}  // namespace dabs::analysis
