// SPDX-License-Identifier: MIT
#include "tcl/domain/RecorderFile.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <cstdio>

#include "materials/InputError.h"

namespace dabs::domain {

namespace {

[[noreturn]] void fail(const std::string& path, const char* what, int error) {
  throw InputError("-file", std::string(what) + " \"" + path + "\": " + std::strerror(error));
}

// Writes all of `text` to `fd`, resuming after partial writes and interrupted calls.
int writeFully(int fd, std::string_view text) {
  while (!text.empty()) {
    const ssize_t n = ::write(fd, text.data(), text.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    text.remove_prefix(static_cast<std::size_t>(n));
  }
  return 0;
}

}  // namespace

RecorderFile::RecorderFile(std::string path) : path_(std::move(path)) {
  fd_ = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd_ < 0) fail(path_, "cannot write", errno);
}

RecorderFile::~RecorderFile() {
  if (!buffer_.empty()) (void)writeFully(fd_, buffer_);
  ::close(fd_);
}

void RecorderFile::flush() {
  if (buffer_.empty()) return;
  // The buffer is emptied even on failure: the error stops the analysis, and a retry would only
  // repeat rows that partly reached the file.
  const int error = writeFully(fd_, buffer_);
  buffer_.clear();
  if (error != 0) fail(path_, "cannot write", error);
}

void RecorderFile::rewrite() {
  // Not a regular file (a pipe, a device such as /dev/full): the text is appended instead.
  if (::lseek(fd_, 0, SEEK_SET) == 0 && ::ftruncate(fd_, 0) != 0 && errno != EINVAL) {
    const int error = errno;
    buffer_.clear();
    fail(path_, "cannot rewrite", error);
  }
  flush();
}

void RecorderFile::replaceAtomically(const std::string& path,
                                     std::initializer_list<std::string_view> parts) {
  const std::string tmp = path + ".tmp";
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) fail(tmp, "cannot write", errno);
  for (std::string_view part : parts)
    if (const int error = writeFully(fd, part)) {
      ::close(fd);
      std::remove(tmp.c_str());
      fail(tmp, "cannot write", error);
    }
  if (::close(fd) != 0) fail(tmp, "cannot write", errno);
  if (std::rename(tmp.c_str(), path.c_str()) != 0) fail(path, "cannot replace", errno);
}

}  // namespace dabs::domain
