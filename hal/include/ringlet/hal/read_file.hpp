#pragma once
// The one way Ringlet reads an input file (configuration, world, colour table, model, dataset
// JSON): only regular files, never more than a stated limit, and a message that names the file and
// says what is wrong with it. A FIFO, a directory or /dev/zero is refused before a byte is read, so
// a bad path can neither block the start-up nor eat the memory.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace ringlet::hal {

/// Limits per kind of file; generous for what each holds, small enough to refuse garbage quickly.
inline constexpr std::size_t kMaxTextFileBytes = 4u << 20;    // configuration, world, model, JSON: 4 MiB
inline constexpr std::size_t kMaxBinaryFileBytes = 64u << 20;  // colour table, images: 64 MiB

struct FileRead {
  std::string bytes;  // the whole file when `error` is empty
  std::string error;  // "<path>: <what is wrong>" (e.g. "not a regular file (a directory)")
  [[nodiscard]] bool ok() const noexcept { return error.empty(); }
};

/// Reads `path` whole. Refuses (with `error` set and `bytes` empty) a path that does not exist,
/// is not a regular file (directory, FIFO, device, socket), is larger than `max_bytes`, or fails
/// to read. `what` names the file's role in the message ("configuration file", "world file").
[[nodiscard]] FileRead read_file(const std::filesystem::path& path, std::string_view what,
                                 std::size_t max_bytes = kMaxTextFileBytes);

/// An input file held open, for a reader that streams it (the HAL log) instead of reading it whole;
/// read_file() opens its files the same way. Closes the file when destroyed.
class InputFile {
 public:
  InputFile() = default;
  ~InputFile();
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;

  /// Opens `path` read-only; refuses anything but a regular file, without blocking on a FIFO.
  /// Returns "" or why it cannot ("not a regular file (a FIFO)", or the system's reason); the
  /// caller puts the path and the file's role in front.
  [[nodiscard]] std::string open(const std::filesystem::path& path);

  [[nodiscard]] int fd() const noexcept { return fd_; }                 // -1 until open() succeeds
  [[nodiscard]] std::uint64_t size() const noexcept { return size_; }  // when opened

 private:
  int fd_ = -1;
  std::uint64_t size_ = 0;
};

}  // namespace ringlet::hal
