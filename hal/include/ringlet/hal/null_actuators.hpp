#pragma once
// Actuators that drive nothing but honour the safe-state contract (latched, any thread): for tools
// and benchmarks that run an executive with no robot attached.
#include <atomic>

#include "ringlet/hal/robot.hpp"

namespace ringlet::hal {

class NullActuators final : public Actuators {
 public:
  void write(const ActuatorCommand& /*cmd*/) noexcept override {}
  void enter_safe_state() noexcept override { safe_.store(true, std::memory_order_relaxed); }
  [[nodiscard]] bool in_safe_state() const noexcept override { return safe_.load(std::memory_order_relaxed); }

 private:
  std::atomic<bool> safe_{false};
};

}  // namespace ringlet::hal
