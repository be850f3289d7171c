#include "progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace ringlet::experiments {

Progress::Progress(bool quiet) : quiet_(quiet), tty_(isatty(STDERR_FILENO) == 1) {}

void Progress::begin(const std::string& what, std::size_t steps) {
  const std::lock_guard lock(mutex_);
  what_ = what;
  steps_ = steps;
  done_ = 0;
  if (!quiet_ && tty_) draw_locked("");
}

void Progress::step(const std::string& detail, std::size_t count) {
  const std::lock_guard lock(mutex_);
  done_ = std::min(steps_, done_ + count);
  if (quiet_) return;
  if (tty_) {
    draw_locked(detail);
  } else {
    std::fprintf(stderr, "ringlet-experiments: %s: %zu/%zu %s\n", what_.c_str(), done_, steps_, detail.c_str());
  }
}

void Progress::end() {
  const std::lock_guard lock(mutex_);
  if (!quiet_ && tty_) std::fputc('\n', stderr);
}

void Progress::draw_locked(const std::string& detail) {
  constexpr std::size_t kWidth = 30;
  const std::size_t filled = steps_ == 0 ? kWidth : done_ * kWidth / steps_;
  std::string bar(filled, '#');
  bar.resize(kWidth, '.');
  std::fprintf(stderr, "\r\033[K%-26s [%s] %zu/%zu %s", what_.c_str(), bar.c_str(), done_, steps_, detail.c_str());
  std::fflush(stderr);
}

}  // namespace ringlet::experiments
