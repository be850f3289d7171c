#pragma once
// An output of the binary (--report, --svg), claimed before the run and written at its end.
// Claiming creates a temporary file in the target's folder, so a path that cannot be written (no
// such folder, a directory, no permission) is refused in the first second rather than after the
// whole run. Writing fills the temporary file and renames it over the target: a reader never sees
// half a file, and a run that fails leaves an earlier file of that name untouched.
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

namespace ringlet::firmware {

/// "<flag> <path>: cannot write <what>: <why>". The binary exits 2 when claiming fails.
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class PendingOutput {
 public:
  /// Checks `path` and creates the temporary file next to it; throws OutputError. The target may
  /// be missing or a regular file (a symbolic link is followed); anything else is refused.
  PendingOutput(const std::filesystem::path& path, std::string_view flag, std::string_view what);
  /// Removes the temporary file if commit() did not rename it.
  ~PendingOutput();
  PendingOutput(const PendingOutput&) = delete;
  PendingOutput& operator=(const PendingOutput&) = delete;

  /// Writes `content` to the temporary file and renames it over the target. Returns an empty
  /// string on success, else the message (and the target is left as it was). Call once.
  [[nodiscard]] std::string commit(std::string_view content);

  [[nodiscard]] const std::filesystem::path& path() const noexcept { return path_; }

 private:
  [[nodiscard]] std::string message(const std::string& why) const;
  void discard() noexcept;

  std::filesystem::path path_;    // as given, for messages
  std::filesystem::path target_;  // where the rename goes (a symbolic link resolved)
  std::filesystem::path temporary_;
  std::string flag_;
  std::string what_;
  int fd_ = -1;
};

}  // namespace ringlet::firmware
