#pragma once
// Tasks that exist only in the tests, added the way a new production task is: this file (a class
// with kDeclaration and make()), one registry line (TaskRegistry::add), one table row.
#include <cstdio>
#include <memory>

#include "ringlet/executive/task.hpp"
#include "ringlet/firmware/task_declaration.hpp"
#include "ringlet/firmware/task_services.hpp"
#include "ringlet/whiteboard/whiteboard.hpp"

namespace ringlet::firmware::test {

/// Reads the pose and prints where the robot is, as the Mi-Pal Print message.
class PrintPoseTask final : public executive::Task {
 public:
  static constexpr TaskDeclaration kDeclaration{"print_pose", kTypeNames<wb::Pose>, kTypeNames<wb::Print>,
                                                here()};
  static std::unique_ptr<executive::Task> make(TaskServices& services) {
    return std::make_unique<PrintPoseTask>(services.board);
  }
  explicit PrintPoseTask(wb::Whiteboard& board) noexcept : board_(board) {}
  void run(const executive::TaskContext& /*ctx*/) noexcept override {
    const wb::Pose pose = board_.get<wb::Pose>();
    char text[64];
    std::snprintf(text, sizeof text, "at %.2f %.2f", pose.x, pose.y);
    wb::Print print{};
    print.text = text;
    board_.post(print);
  }
  [[nodiscard]] hal::Nanos modelled_cost() const noexcept override { return hal::Nanos{2'000}; }

 private:
  wb::Whiteboard& board_;
};

/// Needs field lines, which nothing in a camera-less configuration provides.
class NeedsLinesTask final : public executive::Task {
 public:
  static constexpr TaskDeclaration kDeclaration{"needs_lines", kTypeNames<wb::FieldLines>, kNoTypes,
                                                here()};
  static std::unique_ptr<executive::Task> make(TaskServices& /*services*/) { return std::make_unique<NeedsLinesTask>(); }
  void run(const executive::TaskContext& /*ctx*/) noexcept override {}
};

}  // namespace ringlet::firmware::test
