// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace dabs::parallel {

/// One row of results: (column, value) pairs in column order.
using Record = std::vector<std::pair<std::string, std::string>>;

/// The results of an ensemble on disk: one file per job, `<dir>/jobs/<id>.csv` (a header line and
/// one row), written atomically (a temporary file renamed over the final name once complete and
/// flushed to disk), so a run killed at any moment leaves every result file either absent or whole;
/// and one merged CSV of every job. CSV follows RFC 4180: a field holding a comma, a quote or a
/// line break is quoted, quotes doubled.
class ResultStore {
 public:
  /// Uses `dir` (created with its `jobs` folder when missing).
  explicit ResultStore(std::filesystem::path dir);

  /// File of job `id`.
  std::filesystem::path jobFile(const std::string& id) const;
  /// Writes `csv` (from toCsv) as job `id`'s result, atomically.
  void write(const std::string& id, const std::string& csv) const;
  /// Job `id`'s result, or nullopt when there is none or the file is not a whole result.
  std::optional<Record> read(const std::string& id) const;
  /// Writes the rows in one CSV, atomically: the columns are those of every row in order of first
  /// appearance, a missing value is empty.
  void writeMerged(const std::vector<Record>& rows, const std::filesystem::path& file) const;

  /// A record as CSV: header line and one row, each ending in a newline.
  static std::string toCsv(const Record& record);
  /// The record of a CSV text from toCsv; nullopt when it is not one (wrong number of lines or
  /// fields, missing final newline).
  static std::optional<Record> fromCsv(std::string_view text);
  /// Writes `text` to `file` atomically (temporary file in the same folder, fsync, rename).
  static void writeAtomically(const std::filesystem::path& file, std::string_view text);

 private:
  std::filesystem::path dir_;
};

}  // namespace dabs::parallel
