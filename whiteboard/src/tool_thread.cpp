#include "ringlet/whiteboard/tool_thread.hpp"

#include "ringlet/whiteboard/whiteboard.hpp"

namespace ringlet::wb {

ToolThread::ToolThread(Whiteboard& wb, std::chrono::milliseconds period)
    : wb_(wb), period_(period), thread_([this] { run(); }) {}

ToolThread::~ToolThread() {
  {
    const std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void ToolThread::run() {
  std::unique_lock lock(mutex_);
  while (!stop_) {
    lock.unlock();
    wb_.deliver_tool_subscriptions();
    lock.lock();
    wake_.wait_for(lock, period_, [this] { return stop_; });
  }
  // One last pass so that what was posted before stop() is not silently dropped.
  lock.unlock();
  wb_.deliver_tool_subscriptions();
}

}  // namespace ringlet::wb
