// SPDX-License-Identifier: MIT
// RecorderFile: text reaches the file at each flush (read back through a second descriptor while
// the file is still open), rewrite replaces the whole file, and a write error throws.
#include "tcl/domain/RecorderFile.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <unistd.h>

#include "materials/InputError.h"

namespace dabs::domain {
namespace {

std::string contents(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::filesystem::path tempPath(const char* name) {
  return std::filesystem::temp_directory_path() /
         (std::string("dabs-recorderfile-") + std::to_string(::getpid()) + "-" + name);
}

TEST(RecorderFileTest, EachFlushReachesTheFileWhileItStaysOpen) {
  const auto path = tempPath("rows.out");
  {
    RecorderFile file(path.string());
    EXPECT_EQ(contents(path), "");
    file.buffer() += "0.1 1\n";
    EXPECT_EQ(contents(path), "") << "nothing is written before flush";
    file.flush();
    EXPECT_EQ(contents(path), "0.1 1\n");
    file.buffer() += "0.2 2\n";
    file.flush();
    EXPECT_EQ(contents(path), "0.1 1\n0.2 2\n");
    EXPECT_TRUE(file.buffer().empty());
  }
  std::filesystem::remove(path);
}

TEST(RecorderFileTest, RewriteReplacesTheWholeFile) {
  const auto path = tempPath("envelope.out");
  {
    RecorderFile file(path.string());
    file.buffer() += "-1 -1\n2 2\n2 2\n";
    file.rewrite();
    file.buffer() += "-3\n4\n4\n";
    file.rewrite();
    EXPECT_EQ(contents(path), "-3\n4\n4\n");
  }
  std::filesystem::remove(path);
}

TEST(RecorderFileTest, OpeningTruncatesAnOldFile) {
  const auto path = tempPath("old.out");
  std::ofstream(path) << "old rows\n";
  { RecorderFile file(path.string()); }
  EXPECT_EQ(contents(path), "");
  std::filesystem::remove(path);
}

TEST(RecorderFileTest, AFullDiskThrowsNamingTheFile) {
  if (!std::filesystem::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  RecorderFile file("/dev/full");
  file.buffer() += "1 2 3\n";
  try {
    file.flush();
    FAIL() << "a write to /dev/full must throw";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/dev/full"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(file.buffer().empty());
}

TEST(RecorderFileTest, AFileThatCannotBeOpenedThrows) {
  EXPECT_THROW(RecorderFile("/nonexistent-folder/rows.out"), InputError);
}

TEST(RecorderFileTest, ReplaceAtomicallyWritesAllParts) {
  const auto path = tempPath("page.html");
  RecorderFile::replaceAtomically(path.string(), {"<a>", "data", "</a>"});
  EXPECT_EQ(contents(path), "<a>data</a>");
  EXPECT_FALSE(std::filesystem::exists(path.string() + ".tmp"));
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace dabs::domain
