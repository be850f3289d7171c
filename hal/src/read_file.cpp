#include "ringlet/hal/read_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <system_error>

namespace ringlet::hal {
namespace {

const char* kind_of(mode_t mode) noexcept {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

}  // namespace

InputFile::~InputFile() {
  if (fd_ >= 0) ::close(fd_);
}

std::string InputFile::open(const std::filesystem::path& path) {
  if (fd_ >= 0) ::close(fd_);
  size_ = 0;
  // O_NONBLOCK: opening a FIFO with no writer must not wait; fstat then refuses it.
  fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY);
  if (fd_ < 0) return std::generic_category().message(errno);
  struct stat st {};
  std::string refused;
  if (::fstat(fd_, &st) != 0) {
    refused = std::generic_category().message(errno);
  } else if (!S_ISREG(st.st_mode)) {
    refused = std::string("not a regular file (") + kind_of(st.st_mode) + ")";
  }
  if (!refused.empty()) {
    ::close(fd_);
    fd_ = -1;
    return refused;
  }
  size_ = static_cast<std::uint64_t>(st.st_size);
  return {};
}

FileRead read_file(const std::filesystem::path& path, std::string_view what, std::size_t max_bytes) {
  FileRead r;
  const std::string name = path.string();
  const auto fail = [&](const std::string& why) {
    r.bytes.clear();
    r.error = name + ": cannot read " + std::string(what) + ": " + why;
    return r;
  };
  InputFile f;
  if (std::string refused = f.open(path); !refused.empty()) return fail(refused);
  const std::uint64_t size = f.size();
  if (size > max_bytes) {
    return fail("too large (" + std::to_string(size) + " bytes; the limit is " + std::to_string(max_bytes) + ")");
  }
  r.bytes.resize(static_cast<std::size_t>(size));
  std::size_t got = 0;
  while (got < r.bytes.size()) {
    const ssize_t n = ::read(f.fd(), r.bytes.data() + got, r.bytes.size() - got);
    if (n < 0) {
      if (errno == EINTR) continue;
      return fail(std::generic_category().message(errno));
    }
    if (n == 0) break;  // shrank while we read: take what is there
    got += static_cast<std::size_t>(n);
  }
  r.bytes.resize(got);
  // Grew while we read: refuse rather than read without limit.
  char extra = 0;
  if (::read(f.fd(), &extra, 1) > 0) return fail("changed size while being read");
  return r;
}

}  // namespace ringlet::hal
