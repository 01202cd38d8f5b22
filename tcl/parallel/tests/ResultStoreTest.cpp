// SPDX-License-Identifier: MIT
#include "tcl/parallel/ResultStore.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace dabs::parallel {
namespace {

std::filesystem::path freshDir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("dabs-store-" + name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  return dir;
}

std::string readAll(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(ResultStoreTest, CsvQuotesFieldsWithCommasQuotesAndLineBreaks) {
  const Record record = {{"job", "a"}, {"error", "x, \"y\"\nz"}, {"peak", "0.125"}};
  const std::string csv = ResultStore::toCsv(record);
  // RFC 4180: quoted field, inner quotes doubled.
  EXPECT_EQ(csv, "job,error,peak\na,\"x, \"\"y\"\"\nz\",0.125\n");
  const auto back = ResultStore::fromCsv(csv);
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(*back, record);
}

TEST(ResultStoreTest, RejectsTextThatIsNotOneWholeRecord) {
  EXPECT_FALSE(ResultStore::fromCsv("job,peak\na,1").has_value());      // no final newline
  EXPECT_FALSE(ResultStore::fromCsv("job,peak\na\n").has_value());      // fields differ
  EXPECT_FALSE(ResultStore::fromCsv("job,peak\n").has_value());         // header only
  EXPECT_FALSE(ResultStore::fromCsv("job,peak\na,\"1\n").has_value());  // open quote
  EXPECT_FALSE(ResultStore::fromCsv("job\na\nb\n").has_value());        // two rows
}

TEST(ResultStoreTest, WritesEachJobAtomicallyAndReadsItBack) {
  const auto dir = freshDir("write");
  ResultStore store(dir);
  const Record record = {{"job", "j1"}, {"status", "ok"}, {"peak", "1.5"}};
  store.write("j1", ResultStore::toCsv(record));
  EXPECT_EQ(store.read("j1"), record);
  EXPECT_FALSE(store.read("j2").has_value());
  // Only the final file is left: the temporary one was renamed.
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir / "jobs")) {
    ++files;
    EXPECT_EQ(entry.path().filename(), "j1.csv");
  }
  EXPECT_EQ(files, 1);
  // A file cut short (written by something else) is not taken for a result.
  std::ofstream(store.jobFile("j3")) << "job,status\nj3,o";
  EXPECT_FALSE(store.read("j3").has_value());
  std::filesystem::remove_all(dir);
}

TEST(ResultStoreTest, MergedCsvHasEveryColumnInOrderOfFirstAppearance) {
  const auto dir = freshDir("merge");
  ResultStore store(dir);
  const std::vector<Record> rows = {{{"job", "a"}, {"x", "1"}},
                                    {{"job", "b"}, {"y", "2"}, {"x", "3"}}};
  store.writeMerged(rows, dir / "results.csv");
  EXPECT_EQ(readAll(dir / "results.csv"), "job,x,y\na,1,\nb,3,2\n");
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace dabs::parallel
