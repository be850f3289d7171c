#include "ringlet/hal/log_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <system_error>
#include <utility>

namespace ringlet::hal {

LogFile::LogFile(std::string path, std::string what) : path_(std::move(path)), what_(std::move(what)) {}

LogFile::~LogFile() {
  if (fd_ >= 0) ::close(fd_);
}

std::string LogFile::create() {
  const std::string prefix = path_ + ": cannot create " + what_ + ": ";
  // O_NONBLOCK: a FIFO without a reader fails at once (ENXIO) instead of blocking the start-up.
  fd_ = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC | O_NONBLOCK | O_NOCTTY, 0644);
  if (fd_ < 0) return prefix + std::generic_category().message(errno);
  struct stat st {};
  if (::fstat(fd_, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd_);
    fd_ = -1;
    return prefix + "not a regular file";
  }
  return {};
}

void LogFile::fail_write(int err) {
  if (error_.empty()) error_ = path_ + ": cannot write " + what_ + ": " + std::generic_category().message(err);
}

bool LogFile::write_all(const void* data, std::size_t size) {
  const auto* bytes = static_cast<const unsigned char*>(data);
  std::size_t done = 0;
  while (!failed() && done < size) {
    const ssize_t n = ::write(fd_, bytes + done, size - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      fail_write(errno);
      break;
    }
    done += static_cast<std::size_t>(n);
  }
  return !failed();
}

bool LogFile::close() {
  if (fd_ >= 0) {
    if (::close(fd_) != 0) fail_write(errno);
    fd_ = -1;
  }
  return !failed();
}

}  // namespace ringlet::hal
