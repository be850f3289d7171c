#pragma once
// An output log file (the HAL log, the whiteboard log): created fresh, written whole or not at all,
// and closed with its errors reported. One writer thread uses it; it never throws, so each log
// keeps its own exception type and the messages stay "<path>: cannot create|write <what>: <why>".
#include <cstddef>
#include <string>

namespace ringlet::hal {

class LogFile {
 public:
  /// `what` names the log in the messages ("HAL log", "whiteboard log").
  LogFile(std::string path, std::string what);
  ~LogFile();  // closes a file still open, silently (close() is the way to learn of an error)
  LogFile(const LogFile&) = delete;
  LogFile& operator=(const LogFile&) = delete;

  /// Creates (or truncates) the file. Refuses anything but a regular file (a FIFO without a reader
  /// fails at once instead of blocking). Returns "" or "<path>: cannot create <what>: <why>".
  [[nodiscard]] std::string create();

  /// Writes all `size` bytes, retrying interrupted writes. False when this or an earlier write
  /// failed: error() says why, and nothing more is written.
  bool write_all(const void* data, std::size_t size);

  /// Closes the file. False when a write failed or the close did (then error() is
  /// "<path>: cannot write <what>: <why>"); error() keeps the first failure.
  bool close();

  [[nodiscard]] bool failed() const noexcept { return !error_.empty(); }
  [[nodiscard]] const std::string& error() const noexcept { return error_; }

 private:
  void fail_write(int err);

  std::string path_;
  std::string what_;
  int fd_ = -1;
  std::string error_;
};

}  // namespace ringlet::hal
