#include "ringlet/firmware/output_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <system_error>
#include <vector>

namespace ringlet::firmware {
namespace fs = std::filesystem;
namespace {

std::string errno_text(int error) { return std::generic_category().message(error); }

const char* kind_of(fs::file_type type) noexcept {
  switch (type) {
    case fs::file_type::directory: return "a directory";
    case fs::file_type::fifo: return "a FIFO";
    case fs::file_type::character: return "a character device";
    case fs::file_type::block: return "a block device";
    case fs::file_type::socket: return "a socket";
    default: return "not a regular file";
  }
}

// The permissions a plain open(O_CREAT, 0666) would give, which mkstemp's 0600 does not.
mode_t default_file_mode() noexcept {
  const mode_t mask = ::umask(0);
  ::umask(mask);
  return 0666 & ~mask;
}

}  // namespace

std::string PendingOutput::message(const std::string& why) const {
  return flag_ + " " + path_.string() + ": cannot write " + what_ + ": " + why;
}

PendingOutput::PendingOutput(const fs::path& path, std::string_view flag, std::string_view what)
    : path_(path), target_(path), flag_(flag), what_(what) {
  if (path.empty()) throw OutputError(flag_ + ": needs a file name");
  std::error_code ec;
  if (fs::is_symlink(fs::symlink_status(path, ec))) {
    target_ = fs::weakly_canonical(path, ec);
    if (ec) throw OutputError(message("cannot follow the symbolic link: " + ec.message()));
  }
  const fs::file_status status = fs::status(target_, ec);
  if (fs::exists(status) && !fs::is_regular_file(status)) {
    throw OutputError(message(std::string("the path is ") + kind_of(status.type()) + ", not a file"));
  }
  if (target_.filename().empty() || target_.filename() == "." || target_.filename() == "..") {
    throw OutputError(message("the path names a directory, not a file"));
  }
  const fs::path folder = target_.has_parent_path() ? target_.parent_path() : fs::path(".");
  const fs::file_status folder_status = fs::status(folder, ec);
  if (!fs::exists(folder_status)) throw OutputError(message("the folder " + folder.string() + " does not exist"));
  if (!fs::is_directory(folder_status)) throw OutputError(message(folder.string() + " is not a folder"));

  // A hidden name next to the target: the rename at the end stays within one file system.
  std::string pattern = (folder / ("." + target_.filename().string() + ".XXXXXX")).string();
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  fd_ = ::mkostemp(name.data(), O_CLOEXEC);
  if (fd_ < 0) throw OutputError(message("cannot create a file in " + folder.string() + ": " + errno_text(errno)));
  temporary_ = name.data();
  if (::fchmod(fd_, default_file_mode()) != 0) {
    const int error = errno;
    discard();
    throw OutputError(message("cannot set the file's permissions: " + errno_text(error)));
  }
}

PendingOutput::~PendingOutput() { discard(); }

void PendingOutput::discard() noexcept {
  if (fd_ >= 0) {
    ::close(fd_);
    fd_ = -1;
  }
  if (!temporary_.empty()) {
    ::unlink(temporary_.c_str());
    temporary_.clear();
  }
}

std::string PendingOutput::commit(std::string_view content) {
  if (fd_ < 0) return message("already written or discarded");
  std::size_t done = 0;
  while (done < content.size()) {
    const ssize_t n = ::write(fd_, content.data() + done, content.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      const int error = errno;
      discard();
      return message(errno_text(error));
    }
    done += static_cast<std::size_t>(n);
  }
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) {
    const int error = errno;
    discard();
    return message(errno_text(error));
  }
  if (::rename(temporary_.c_str(), target_.c_str()) != 0) {
    const int error = errno;
    discard();
    return message("cannot rename the finished file into place: " + errno_text(error));
  }
  temporary_.clear();
  return {};
}

}  // namespace ringlet::firmware
