#pragma once
// The whiteboard's non-real-time delivery thread for kToolThread subscriptions. It polls the rings
// (it never asks the writer to notify anything, so posting cannot block on it) and sleeps on a
// condition variable that only stop uses, so stopping is prompt.
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>

namespace ringlet::wb {

class Whiteboard;

class ToolThread {
 public:
  ToolThread(Whiteboard& wb, std::chrono::milliseconds period);
  ~ToolThread();  // stops and joins
  ToolThread(const ToolThread&) = delete;
  ToolThread& operator=(const ToolThread&) = delete;

 private:
  void run();

  Whiteboard& wb_;
  std::chrono::milliseconds period_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stop_ = false;  // guarded by mutex_
  std::thread thread_;
};

}  // namespace ringlet::wb
