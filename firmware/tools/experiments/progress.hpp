#pragma once
// Progress on stderr: a bar redrawn in place when stderr is a terminal, else one plain line per
// finished step (a log stays readable). Thread-safe: workers report as they finish. It writes
// nothing that any result depends on.
#include <cstddef>
#include <mutex>
#include <string>

namespace ringlet::experiments {

class Progress {
 public:
  /// `quiet`: print nothing.
  explicit Progress(bool quiet);
  /// A new phase of `steps` steps, named `what`.
  void begin(const std::string& what, std::size_t steps);
  /// `count` steps of the phase done (a bar is never drawn past its end); `detail` says which.
  void step(const std::string& detail, std::size_t count = 1);
  /// The phase is over (ends the bar's line).
  void end();

 private:
  void draw_locked(const std::string& detail);

  bool quiet_;
  bool tty_;
  std::mutex mutex_;
  std::string what_;
  std::size_t steps_ = 0;
  std::size_t done_ = 0;
};

}  // namespace ringlet::experiments
