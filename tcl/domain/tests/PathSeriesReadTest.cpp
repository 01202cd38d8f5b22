// SPDX-License-Identifier: MIT
// Reading a record as OpenSees' PathSeries does (`file >> value` until it fails): a number needs no
// space after it, and the first text that does not start a number ends the record.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

#include <unistd.h>

#include "materials/InputError.h"
#include "tcl/domain/PathSeries.h"

namespace dabs::domain {
namespace {

std::vector<double> readText(const std::string& text) {
  // One file per process: ctest runs this suite's tests in parallel processes.
  const std::string path =
      ::testing::TempDir() + "dabs_path_series_read_" + std::to_string(::getpid()) + ".txt";
  {
    std::ofstream f(path);
    f << text;
  }
  const RecordFile r = readRecordFile(path);
  std::remove(path.c_str());
  return r.values;
}

TEST(PathSeriesReadTest, TrailerEndsTheRecordAndKeepsTheValuesRead) {
  EXPECT_EQ(readText("0.1 0.2\n-0.3 4e-1\n*** End Data ***\n9 9\n"),
            (std::vector<double>{0.1, 0.2, -0.3, 0.4}));
}

TEST(PathSeriesReadTest, NumberNeedsNoSpaceAfterIt) {
  // "0.2***" gives 0.2; "1.5-3" gives 1.5 and -3 (stream extraction stops at the second sign);
  // an exponent marker without digits makes the extraction fail, which ends the record.
  EXPECT_EQ(readText("1.5-3 0.2*** 7"), (std::vector<double>{1.5, -3.0, 0.2}));
  EXPECT_EQ(readText("4 2e 5"), (std::vector<double>{4.0}));
  EXPECT_EQ(readText(".5 -.25 +3."), (std::vector<double>{0.5, -0.25, 3.0}));
}

TEST(PathSeriesReadTest, NoNumberAtAllIsAnError) {
  EXPECT_THROW(readText("*** no data ***\n1 2 3\n"), InputError);
}

}  // namespace
}  // namespace dabs::domain
