// The simulated camera's render time per 640×480 frame on the SPL field (target: < 10 ms on one
// core in release), with and without the BT.601 YUYV conversion, and the ground truth's share.
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "ringlet/sim_hal/camera_renderer.hpp"
#include "ringlet/hal/yuv.hpp"

namespace {

using namespace ringlet;

/// The shipped SPL field in its own look (the SPL look: NAO-shaped robots, noise, drift), or in
/// the first renderer's plain look for comparison.
sim_hal::CameraRenderer make_renderer(bool plain = false) {
  sim_hal::World world = sim_hal::load_world(RINGLET_SIM_WORLDS_DIR "/spl_field.world");
  if (plain) world.look = sim_hal::CameraLook{};
  return sim_hal::CameraRenderer(std::move(world), sim_hal::CameraSpec{}, 7);
}

// A typical view: from the own half towards the centre circle, a robot and the ball in view.
const hal::Pose2 kPose{-2.0, -0.4, hal::deg_to_rad(80.0)};
const hal::HeadJoints kHead{0.1, 0.3};

void BM_RenderSplField(benchmark::State& state) {
  sim_hal::CameraRenderer renderer = make_renderer();
  for (auto _ : state) {
    renderer.render(kPose, kHead);
    benchmark::DoNotOptimize(renderer.bgr().data());
  }
}
BENCHMARK(BM_RenderSplField)->Unit(benchmark::kMillisecond);

void BM_RenderSplFieldPlainLook(benchmark::State& state) {
  sim_hal::CameraRenderer renderer = make_renderer(true);
  for (auto _ : state) {
    renderer.render(kPose, kHead);
    benchmark::DoNotOptimize(renderer.bgr().data());
  }
}
BENCHMARK(BM_RenderSplFieldPlainLook)->Unit(benchmark::kMillisecond);

// The dataset's heavy case: the SPL look with motion blur, and a NAO robot filling the view.
void BM_RenderSplFieldBlurAndCloseRobot(benchmark::State& state) {
  sim_hal::World world = sim_hal::load_world(RINGLET_SIM_WORLDS_DIR "/spl_field.world");
  world.look.blur = 6;
  world.circles.push_back(sim_hal::Circle{{-2.0 + 0.8 * std::sin(kPose.theta), -0.4 + 0.8 * std::cos(kPose.theta)}, 0.15,
                                          0.574, sim_hal::ObstacleKind::kRobot});
  sim_hal::CameraRenderer renderer(std::move(world), sim_hal::CameraSpec{}, 7);
  for (auto _ : state) {
    renderer.render(kPose, kHead);
    benchmark::DoNotOptimize(renderer.bgr().data());
  }
}
BENCHMARK(BM_RenderSplFieldBlurAndCloseRobot)->Unit(benchmark::kMillisecond);

void BM_RenderSplFieldLookingUp(benchmark::State& state) {
  sim_hal::CameraRenderer renderer = make_renderer();
  for (auto _ : state) {
    renderer.render(kPose, hal::HeadJoints{0.0, -0.1});  // half the picture above the horizon
    benchmark::DoNotOptimize(renderer.bgr().data());
  }
}
BENCHMARK(BM_RenderSplFieldLookingUp)->Unit(benchmark::kMillisecond);

void BM_BgrToYuyv(benchmark::State& state) {
  sim_hal::CameraRenderer renderer = make_renderer();
  renderer.render(kPose, kHead);
  std::vector<std::uint8_t> yuyv(640U * 480U * 2U);
  for (auto _ : state) {
    hal::bgr_to_yuyv(renderer.bgr(), 640, 480, yuyv);
    benchmark::DoNotOptimize(yuyv.data());
  }
}
BENCHMARK(BM_BgrToYuyv)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
