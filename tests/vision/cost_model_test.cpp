// The work count and the cost model: counted from the frame, the head and the level only (so the
// same frame costs the same on every host and under any stopwatch), smaller at higher degrade
// levels, and a plain weighted sum.
#include <gtest/gtest.h>

#include "ringlet/vision/cost_model.hpp"
#include "ringlet/vision/pipeline.hpp"
#include "synthetic_field.hpp"

namespace ringlet::vision {
namespace {

/// A slow host: a millisecond passes at every read. The deadline is far away and decides nothing,
/// but every stage time differs from the plain run.
class SlowHostStopwatch final : public hal::Stopwatch {
 public:
  [[nodiscard]] hal::Nanos wall_now() const noexcept override { return hal::Nanos{now_ += 1'000'000}; }
  [[nodiscard]] hal::Nanos cpu_now() const noexcept override { return wall_now(); }

 private:
  mutable std::int64_t now_ = 0;
};

TEST(VisionCost, TheWorkCountDependsOnTheFrameNotOnTheClock) {
  testing::Camera cam;
  const auto frame = testing::render(testing::field_scene(), cam, hal::PixelFormat::kYuyv);
  VisionPipeline a(VisionConfig{}, ColourTable::from_thresholds({}));
  VisionPipeline b(VisionConfig{}, ColourTable::from_thresholds({}));
  const WorkCount plain = a.process(frame.view, cam.head).work;
  SlowHostStopwatch watch;
  const WorkCount timed = b.process(frame.view, cam.head, Deadline{&watch, hal::Nanos{std::int64_t{1} << 60}, false}).work;
  EXPECT_EQ(plain.classified_pixels, timed.classified_pixels);
  EXPECT_EQ(plain.ball_samples, timed.ball_samples);
  EXPECT_EQ(plain.scanned_pixels, timed.scanned_pixels);
  EXPECT_EQ(plain.candidates, timed.candidates);
  EXPECT_EQ(plain.point_tests, timed.point_tests);
  EXPECT_GT(plain.classified_pixels, 100'000);
  EXPECT_GT(plain.point_tests, 0);
  EXPECT_EQ(modelled_cost(plain), modelled_cost(timed));
}

TEST(VisionCost, HigherDegradeLevelsCostLess) {
  testing::Camera cam;
  const auto frame = testing::render(testing::field_scene(), cam, hal::PixelFormat::kYuyv);
  VisionPipeline p(VisionConfig{}, ColourTable::from_thresholds({}));
  hal::Nanos previous = hal::Nanos::max();
  for (int level = 0; level < kDegradeLevels; ++level) {
    const hal::Nanos cost = modelled_cost(p.process(frame.view, cam.head, {}, level).work);
    EXPECT_LT(cost, previous) << "level " << level;
    previous = cost;
  }
  // The shipped model keeps a full frame inside the 3 ms budget the firmware gives vision.
  EXPECT_LT(modelled_cost(p.process(frame.view, cam.head, {}, 0).work), hal::Nanos{3'000'000});
}

TEST(VisionCost, TheModelIsAWeightedSumTimesTheBoardFactor) {
  CostModel m;
  m.board_slowdown = 2.0;
  m.fixed_ns = 100.0;
  m.per_classified_pixel_ns = 1.0;
  m.per_ball_sample_ns = 2.0;
  m.per_scanned_pixel_ns = 3.0;
  m.per_candidate_ns = 4.0;
  m.per_point_test_ns = 5.0;
  const WorkCount w{10, 20, 30, 40, 50};
  EXPECT_EQ(modelled_cost(w, m), hal::Nanos{2 * (100 + 10 + 40 + 90 + 160 + 250)});
  EXPECT_EQ(modelled_cost(WorkCount{}, m), hal::Nanos{200});
}

}  // namespace
}  // namespace ringlet::vision
