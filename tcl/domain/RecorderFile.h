// SPDX-License-Identifier: MIT
#pragma once

#include <initializer_list>
#include <string>
#include <string_view>

namespace dabs::domain {

/// The output file of a recorder, the one place where recorders write: opened (truncated) once
/// when the recorder is created and closed when it is destroyed. Text is collected in a buffer and
/// handed to the operating system by flush(), one write(2) per call, so a row written at a
/// committed step survives a kill of the program (only the page cache stands between it and the
/// disk). Every failed write (a full disk: `-file /dev/full`) throws InputError naming the file.
class RecorderFile {
 public:
  /// Opens `path` for writing, truncating it; throws InputError("-file", ...) when it cannot.
  explicit RecorderFile(std::string path);
  ~RecorderFile();
  RecorderFile(const RecorderFile&) = delete;
  RecorderFile& operator=(const RecorderFile&) = delete;

  /// Text waiting for the next flush(); callers append to it.
  std::string& buffer() noexcept { return buffer_; }
  /// Appends the buffer to the file and empties it; throws InputError on a write error.
  void flush();
  /// Makes the buffer the whole file and empties it (envelope recorders rewrite their rows);
  /// throws InputError.
  void rewrite();
  /// The file name as the user gave it.
  const std::string& path() const noexcept { return path_; }

  /// Writes `parts` to `path + ".tmp"` and renames it to `path`, so a reader never sees half a
  /// file (the viewer page); throws InputError on any failure.
  static void replaceAtomically(const std::string& path,
                                std::initializer_list<std::string_view> parts);

 private:
  std::string path_;
  std::string buffer_;
  int fd_ = -1;
};

}  // namespace dabs::domain
