#pragma once
// A fixed piece of work and the calling thread's CPU time for it: how much slower this machine
// runs the same instructions now than a moment ago. Thread CPU time does not count waiting for a
// core, but it does count what other busy cores cost a running thread: a shared cache, memory
// bandwidth, and on a virtual machine a sibling hyperthread or a neighbour on the same physical
// core. A real-clock test that loads the machine divides that out, so that what it judges is
// what the load does to the controller's own work (spinning, waiting counted as running), not
// what it does to the hardware. Header-only, like cpu_hog.hpp.
#include <time.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>
#include <vector>

namespace ringlet::test {

namespace reference_work_detail {

inline std::atomic<std::uint64_t> sink{0};

inline double thread_cpu_us() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) * 1e6 + static_cast<double>(ts.tv_nsec) * 1e-3;
}

// One camera frame's worth of memory (640x480, two bytes a pixel), as vision reads it.
inline const std::vector<std::uint8_t>& frame() {
  static const std::vector<std::uint8_t> bytes = [] {
    std::vector<std::uint8_t> b(640U * 480U * 2U);
    std::uint32_t x = 12345;
    for (auto& v : b) {
      x = x * 1664525U + 1013904223U;
      v = static_cast<std::uint8_t>(x >> 24);
    }
    return b;
  }();
  return bytes;
}

}  // namespace reference_work_detail

// The median thread CPU time, in microseconds, of `reps` passes over a frame that build a
// histogram of its bytes (loads, a data-dependent store, arithmetic): the shape of vision's and
// sense's work, not of a busy loop's.
inline double reference_work_cpu_us(int reps = 41) {
  using reference_work_detail::thread_cpu_us;
  const auto& bytes = reference_work_detail::frame();
  std::vector<double> samples;
  samples.reserve(static_cast<std::size_t>(reps));
  std::uint64_t sink = 0;
  for (int r = 0; r < reps; ++r) {
    std::array<std::uint32_t, 256> histogram{};
    const double t0 = thread_cpu_us();
    for (std::size_t i = 0; i < bytes.size(); ++i) ++histogram[bytes[i] ^ static_cast<std::uint8_t>(r)];
    const double t1 = thread_cpu_us();
    sink += histogram[static_cast<std::size_t>(r) & 255U];
    samples.push_back(t1 - t0);
  }
  // An observable side effect, so that the passes are not optimised away.
  reference_work_detail::sink.store(sink, std::memory_order_relaxed);
  std::nth_element(samples.begin(), samples.begin() + reps / 2, samples.end());
  return samples[static_cast<std::size_t>(reps / 2)];
}

}  // namespace ringlet::test
