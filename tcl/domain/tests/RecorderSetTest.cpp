// SPDX-License-Identifier: MIT
// The domain's recorder set: tags in the order of addition (restarting only at a wipe), an
// unknown tag is an error, reactions are formed once and only before a recorder that needs them,
// and the first write error is kept while the other recorders go on recording.
#include "tcl/domain/RecorderSet.h"

#include <gtest/gtest.h>

#include "materials/InputError.h"
#include "tcl/domain/Domain.h"

namespace dabs::domain {
namespace {

/// Counts its calls; throws on record when told to.
struct CountingRecorder final : Recorder {
  int* records;
  int* flushes;
  bool reactions = false;
  bool fails = false;
  CountingRecorder(int* r, int* f) : records(r), flushes(f) {}
  void record(const Domain& /*domain*/) override {
    ++*records;
    if (fails) throw InputError("file", "disk full");
  }
  void flush() override { ++*flushes; }
  bool needsReactions() const override { return reactions; }
};

TEST(RecorderSetTest, TagsFollowTheOrderOfAdditionAndRestartOnlyWhenReset) {
  int records = 0, flushes = 0;
  RecorderSet set;
  EXPECT_EQ(set.add(std::make_unique<CountingRecorder>(&records, &flushes)), 0);
  EXPECT_EQ(set.add(std::make_unique<CountingRecorder>(&records, &flushes)), 1);
  set.remove(0);
  EXPECT_EQ(flushes, 1);  // flushed before it goes
  EXPECT_THROW(set.remove(0), InputError);
  EXPECT_EQ(set.add(std::make_unique<CountingRecorder>(&records, &flushes)), 2);
  set.removeAll(false);
  EXPECT_EQ(flushes, 3);
  EXPECT_EQ(set.add(std::make_unique<CountingRecorder>(&records, &flushes)), 3);
  set.removeAll(true);
  EXPECT_EQ(set.add(std::make_unique<CountingRecorder>(&records, &flushes)), 0);
}

TEST(RecorderSetTest, ReactionsOnceBeforeTheFirstRecorderThatNeedsThemAndFirstErrorKept) {
  int records = 0, flushes = 0, reactions = 0;
  Domain domain;
  RecorderSet set;
  auto plain = std::make_unique<CountingRecorder>(&records, &flushes);
  plain->fails = true;
  set.add(std::move(plain));
  for (int k = 0; k < 2; ++k) {
    auto r = std::make_unique<CountingRecorder>(&records, &flushes);
    r->reactions = true;
    r->fails = true;
    set.add(std::move(r));
  }
  set.record(domain, [&] { ++reactions; });
  EXPECT_EQ(records, 3);  // every recorder recorded although each one failed
  EXPECT_EQ(reactions, 1);
  const auto error = set.takeError();
  ASSERT_TRUE(error.has_value());
  EXPECT_EQ(error->rfind("recorder 0: ", 0), 0u);  // the first one's
  EXPECT_FALSE(set.takeError().has_value());
}

}  // namespace
}  // namespace dabs::domain
