// The simulated camera allocates nothing per frame: rendering, ground truth, the hand-over to the
// render thread and delivery all use buffers sized at construction. Every allocation in the
// process (operator new and malloc & co., the render thread's too) is counted
// (tests/support/allocation_counter).
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "allocation_counter.hpp"
#include "ringlet/sim_hal/camera_renderer.hpp"
#include "ringlet/sim_hal/sim_robot.hpp"

namespace ringlet::sim_hal {
namespace {

using ringlet::test::AllocationCounter;

World spl_field() { return load_world(RINGLET_SIM_WORLDS_DIR "/spl_field.world"); }

TEST(SimCameraNoAllocation, TheCounterSeesAnAllocation) {
  AllocationCounter counter;
  auto v = std::make_unique<std::vector<int>>(100, 1);
  EXPECT_GE(counter.count(), 2U);
  EXPECT_EQ(v->size(), 100U);
}

TEST(SimCameraNoAllocation, RenderingAllocatesNothing) {
  CameraRenderer renderer(spl_field(), CameraSpec{}, 1);
  AllocationCounter counter;
  for (int i = 0; i < 20; ++i) {
    renderer.render(hal::Pose2{-3.0 + 0.3 * i, -0.5, 0.1 * i}, hal::HeadJoints{0.05 * i - 0.5, 0.3});
  }
  EXPECT_EQ(counter.count(), 0U);
  EXPECT_FALSE(renderer.truth().lines.empty());
}

TEST(SimCameraNoAllocation, SimRobotWithCameraAllocatesNothingInTheCycle) {
  SimConfig config;
  config.camera.enabled = true;
  SimRobot robot(spl_field(), config);
  hal::SensorFrame frame;
  hal::FrameView view;
  hal::ActuatorCommand cmd;
  cmd.drive = {0.3, 0.8};
  cmd.head = {0.5, 0.3};
  robot.actuators().write(cmd);
  std::uint64_t before = 0;
  std::uint64_t delivered = 0;
  for (int step = 0; step < 90; ++step) {
    robot.sensors().read(frame);
    // Counted from step 6 on: by then read() has waited for a finished render (a capture is
    // delivered one camera period later), so the render thread's start-up is over. Under
    // AddressSanitizer the runtime's own thread start calls pthread_getattr_np, which callocs and
    // reallocs, and would otherwise race into the count.
    if (step == 6) before = ringlet::test::allocations();
    if (robot.camera()->grab_latest(view)) delivered = view.sequence;
    (void)robot.camera_truth();
  }
  EXPECT_EQ(ringlet::test::allocations() - before, 0U);
  EXPECT_EQ(delivered, 29U);
}

}  // namespace
}  // namespace ringlet::sim_hal
