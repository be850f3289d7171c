// process() allocates nothing: the global operator new is replaced in this executable (only) and
// counts every allocation while frames are processed at every degrade level, with and without a
// deadline that cuts RANSAC short.
#include <gtest/gtest.h>

#include <atomic>
#include <cstddef>
#include <cstdlib>
#include <new>

#include "ringlet/vision/pipeline.hpp"
#include "synthetic_field.hpp"

namespace {
std::atomic<std::size_t> g_allocations{0};

void* counted_alloc(std::size_t size, std::size_t align) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (size == 0) size = 1;
  void* p = align <= alignof(std::max_align_t) ? std::malloc(size)
                                               : std::aligned_alloc(align, (size + align - 1) / align * align);
  if (p == nullptr) throw std::bad_alloc{};
  return p;
}
}  // namespace

void* operator new(std::size_t size) { return counted_alloc(size, alignof(std::max_align_t)); }
void* operator new(std::size_t size, std::align_val_t align) { return counted_alloc(size, static_cast<std::size_t>(align)); }
void* operator new[](std::size_t size) { return counted_alloc(size, alignof(std::max_align_t)); }
void* operator new[](std::size_t size, std::align_val_t align) {
  return counted_alloc(size, static_cast<std::size_t>(align));
}
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }

namespace ringlet::vision {
namespace {

class StepWatch final : public hal::Stopwatch {
 public:
  [[nodiscard]] hal::Nanos wall_now() const noexcept override { return hal::Nanos{1000 * reads_++}; }
  [[nodiscard]] hal::Nanos cpu_now() const noexcept override { return wall_now(); }

 private:
  mutable long reads_ = 0;
};

TEST(VisionNoAllocation, ProcessAllocatesNothing) {
  testing::Camera cam;
  const auto yuyv = testing::render(testing::field_scene(), cam, hal::PixelFormat::kYuyv);
  const auto bgr = testing::render(testing::field_scene(), cam, hal::PixelFormat::kBgr8);
  VisionPipeline p(VisionConfig{}, ColourTable::from_thresholds({}));
  StepWatch watch;
  const std::size_t before = g_allocations.load();
  std::size_t lines = 0;
  for (int k = 0; k < 3; ++k) {
    for (int level = 0; level < kDegradeLevels; ++level) {
      lines += p.process(yuyv.view, cam.head, {}, level).line_count;
      lines += p.process(bgr.view, cam.head, {}, level).line_count;
      lines += p.process(yuyv.view, cam.head, Deadline{&watch, watch.wall_now() + hal::Nanos{15000}, false}, level).line_count;
    }
  }
  EXPECT_EQ(g_allocations.load() - before, 0U);
  EXPECT_GT(lines, 0U);
}

}  // namespace
}  // namespace ringlet::vision
