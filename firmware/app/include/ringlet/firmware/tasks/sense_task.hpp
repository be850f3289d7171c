#pragma once
// HAL sensors → whiteboard: the pose measurement, the laser scan and its nearest return, the head's
// posture and the base's state (odometry, bumper, battery), each stamped; and, once a second, the
// link to the board when the backend has one (BoardHealth). On the simulated robot this read is
// also what advances the world by one period.
//
// Two rows of the registry: `sense` posts the GPS-like pose measurement (Powers & Balch's eq. 19,
// the outdoor car's) as Pose; `sense_no_gps` leaves it out, for a robot that has none (the SPL
// field), where the localization task provides Pose. The contract check keeps one provider.
#include <memory>

#include "ringlet/executive/task.hpp"
#include "ringlet/firmware/task_declaration.hpp"
#include "ringlet/firmware/task_services.hpp"
#include "ringlet/hal/sensors.hpp"
#include "ringlet/whiteboard/whiteboard.hpp"

namespace ringlet::firmware {

class SenseTask : public executive::Task {
 public:
  static constexpr TaskDeclaration kDeclaration{
      "sense", kNoTypes, kTypeNames<wb::Pose, wb::LaserSummary, wb::LaserScan, wb::HeadPosture, wb::BodyState, wb::BoardHealth>,
      here()};
  /// HAL read and posting. The simulator's own work inside read() (ray casting the laser, waiting
  /// for the render thread) is not the robot's and is not modelled.
  static constexpr hal::Nanos kModelledCost{40'000};

  static std::unique_ptr<executive::Task> make(TaskServices& services);
  SenseTask(hal::Sensors& sensors, wb::Whiteboard& board, const hal::BoardHealth* health = nullptr,
            bool posts_gps = true) noexcept
      : sensors_(sensors), board_(board), health_(health), posts_gps_(posts_gps) {}
  void run(const executive::TaskContext& ctx) noexcept override;
  [[nodiscard]] hal::Nanos modelled_cost() const noexcept override { return kModelledCost; }

 private:
  hal::Sensors& sensors_;
  wb::Whiteboard& board_;
  const hal::BoardHealth* health_;  // the backend's board, or null
  bool posts_gps_;
  hal::SensorFrame frame_{};  // filled in place by the backend: no copy of the laser per frame
  wb::LaserScan scan_{};      // the scan as posted (millimetres), kept here: 1.5 kB off the stack
};

/// The same without the GPS: everything but Pose.
class SenseNoGpsTask final : public SenseTask {
 public:
  static constexpr TaskDeclaration kDeclaration{
      "sense_no_gps", kNoTypes,
      kTypeNames<wb::LaserSummary, wb::LaserScan, wb::HeadPosture, wb::BodyState, wb::BoardHealth>, here()};
  static std::unique_ptr<executive::Task> make(TaskServices& services);
  using SenseTask::SenseTask;
};

}  // namespace ringlet::firmware
