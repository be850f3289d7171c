// process() allocates nothing: every allocation is counted (tests/support/allocation_counter)
// while frames are processed at every degrade level, with and without a
// deadline that cuts RANSAC short.
#include <gtest/gtest.h>

#include <cstddef>

#include "allocation_counter.hpp"
#include "ringlet/vision/pipeline.hpp"
#include "classify_everything.hpp"
#include "synthetic_field.hpp"


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
  const std::uint64_t before = ringlet::test::allocations();
  std::size_t lines = 0;
  for (int k = 0; k < 3; ++k) {
    for (int level = 0; level < kDegradeLevels; ++level) {
      lines += p.process(yuyv.view, cam.head, {}, level).line_count;
      lines += p.process(bgr.view, cam.head, {}, level).line_count;
      lines += p.process(yuyv.view, cam.head, Deadline{&watch, watch.wall_now() + hal::Nanos{15000}, false}, level).line_count;
    }
  }
  EXPECT_EQ(ringlet::test::allocations() - before, 0U);
  EXPECT_GT(lines, 0U);
}

// The black-and-white ball and the robots, with HOG/SVM classifiers installed (weights that accept
// every window, so every candidate is resampled, described and scored), at every degrade level.
TEST(VisionNoAllocation, HogStagesAllocateNothing) {
  testing::Camera cam;
  const auto yuyv = testing::render(testing::classifier_scene(), cam, hal::PixelFormat::kYuyv);
  const auto pipeline = testing::pipeline_classifying_everything();
  VisionPipeline& p = *pipeline;
  StepWatch watch;
  const std::uint64_t before = ringlet::test::allocations();
  int classified = 0;
  std::size_t balls = 0;
  for (int k = 0; k < 3; ++k) {
    for (int level = 0; level < kDegradeLevels; ++level) {
      const VisionResult& r = p.process(yuyv.view, cam.head, {}, level);
      classified += r.balls.classified + r.robots.classified;
      balls += r.balls.count;
      const VisionResult& cut = p.process(yuyv.view, cam.head, Deadline{&watch, watch.wall_now() + hal::Nanos{6000}, false}, level);
      classified += cut.balls.classified;
    }
  }
  EXPECT_EQ(ringlet::test::allocations() - before, 0U);
  EXPECT_GT(classified, 0);
  EXPECT_GT(balls, 0U);
}

}  // namespace
}  // namespace ringlet::vision
