// SPDX-License-Identifier: MIT
#include "tcl/parallel/ResultStore.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace dabs::parallel {

namespace {

std::string csvField(std::string_view field) {
  if (field.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(field);
  std::string out = "\"";
  for (char c : field) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

std::string csvLine(const std::vector<std::string>& fields) {
  std::string line;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (i > 0) line += ',';
    line += csvField(fields[i]);
  }
  return line + "\n";
}

// Reads the CSV lines of `text` (quoted fields may hold line breaks); nullopt when a quote is not
// closed or the text does not end with a line break.
std::optional<std::vector<std::vector<std::string>>> parseCsv(std::string_view text) {
  std::vector<std::vector<std::string>> lines;
  std::vector<std::string> fields;
  std::string field;
  bool inQuotes = false;
  bool atLineStart = true;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    atLineStart = false;
    if (inQuotes) {
      if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
        field += '"';
        ++i;
      } else if (c == '"') {
        inQuotes = false;
      } else {
        field += c;
      }
    } else if (c == '"') {
      inQuotes = true;
    } else if (c == ',') {
      fields.push_back(std::move(field));
      field.clear();
    } else if (c == '\n') {
      fields.push_back(std::move(field));
      field.clear();
      lines.push_back(std::move(fields));
      fields.clear();
      atLineStart = true;
    } else if (c != '\r') {
      field += c;
    }
  }
  if (inQuotes || !atLineStart) return std::nullopt;
  return lines;
}

[[noreturn]] void fail(const std::string& what, const std::filesystem::path& file) {
  throw std::runtime_error(what + " " + file.string() + ": " + std::strerror(errno));
}

}  // namespace

ResultStore::ResultStore(std::filesystem::path dir) : dir_(std::move(dir)) {
  std::filesystem::create_directories(dir_ / "jobs");
}

std::filesystem::path ResultStore::jobFile(const std::string& id) const {
  return dir_ / "jobs" / (id + ".csv");
}

void ResultStore::write(const std::string& id, const std::string& csv) const {
  writeAtomically(jobFile(id), csv);
}

std::optional<Record> ResultStore::read(const std::string& id) const {
  std::ifstream in(jobFile(id), std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  return fromCsv(text.str());
}

void ResultStore::writeMerged(const std::vector<Record>& rows,
                              const std::filesystem::path& file) const {
  std::vector<std::string> columns;
  for (const Record& row : rows)
    for (const auto& [key, value] : row)
      if (std::find(columns.begin(), columns.end(), key) == columns.end()) columns.push_back(key);
  std::string text = csvLine(columns);
  for (const Record& row : rows) {
    std::vector<std::string> fields(columns.size());
    for (const auto& [key, value] : row)
      fields[static_cast<std::size_t>(std::find(columns.begin(), columns.end(), key) -
                                      columns.begin())] = value;
    text += csvLine(fields);
  }
  writeAtomically(file, text);
}

std::string ResultStore::toCsv(const Record& record) {
  std::vector<std::string> keys;
  std::vector<std::string> values;
  for (const auto& [key, value] : record) {
    keys.push_back(key);
    values.push_back(value);
  }
  return csvLine(keys) + csvLine(values);
}

std::optional<Record> ResultStore::fromCsv(std::string_view text) {
  const auto lines = parseCsv(text);
  if (!lines || lines->size() != 2 || (*lines)[0].size() != (*lines)[1].size()) return std::nullopt;
  Record record;
  for (std::size_t i = 0; i < (*lines)[0].size(); ++i)
    record.emplace_back((*lines)[0][i], (*lines)[1][i]);
  return record;
}

void ResultStore::writeAtomically(const std::filesystem::path& file, std::string_view text) {
  // The temporary name is unique per process, so two processes writing the same result (a job
  // rerun by hand) never share a temporary file; rename replaces the old file in one step.
  std::filesystem::path temp = file;
  temp += ".tmp." + std::to_string(::getpid());
  const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) fail("cannot create", temp);
  std::size_t written = 0;
  while (written < text.size()) {
    const ssize_t n = ::write(fd, text.data() + written, text.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      const int saved = errno;
      ::close(fd);
      ::unlink(temp.c_str());
      errno = saved;
      fail("cannot write", temp);
    }
    written += static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0 || ::close(fd) != 0) {
    ::unlink(temp.c_str());
    fail("cannot flush", temp);
  }
  if (::rename(temp.c_str(), file.c_str()) != 0) {
    ::unlink(temp.c_str());
    fail("cannot rename to", file);
  }
}

}  // namespace dabs::parallel
