#pragma once
// The cycle's one defined point for whiteboard subscriptions (dispatch, in type-id order; the
// --wb-log logger is one of them), and once a second the executive's counters as ExecutiveTiming.
// It is also where remote writes ([remote] accept) reach the whiteboard: the requests the bridge
// accepted since the last frame are posted just before the dispatch, so subscriptions and the
// machines' next turn see them whole, at a frame boundary.
#include <memory>

#include "ringlet/executive/task.hpp"
#include "ringlet/firmware/task_declaration.hpp"
#include "ringlet/firmware/task_services.hpp"
#include "ringlet/remote/inbox.hpp"
#include "ringlet/whiteboard/whiteboard.hpp"

namespace ringlet::firmware {

class WhiteboardTask final : public executive::Task {
 public:
  static constexpr TaskDeclaration kDeclaration{"whiteboard", kNoTypes, kTypeNames<wb::ExecutiveTiming>,
                                                here()};
  static constexpr hal::Nanos kModelledCost{6'000};

  static std::unique_ptr<executive::Task> make(TaskServices& services);
  WhiteboardTask(wb::Whiteboard& board, const executive::Executive* const& executive, wb::MessageLogger* log,
                 remote::Inbox* inbox = nullptr) noexcept
      : board_(board), executive_(executive), log_(log), inbox_(inbox) {}
  void run(const executive::TaskContext& ctx) noexcept override;
  [[nodiscard]] hal::Nanos modelled_cost() const noexcept override { return kModelledCost; }

 private:
  wb::Whiteboard& board_;
  const executive::Executive* const& executive_;
  wb::MessageLogger* log_;
  remote::Inbox* inbox_;
};

}  // namespace ringlet::firmware
