#pragma once
// The firmware's side of remote monitoring ([remote]): the bridge (remote/) over this run's
// whiteboard, started and stopped with the run, and its pacing in lockstep.
//
// On the real clock the bridge publishes from its own thread; the cycle never waits for it. In
// lockstep the run is a pure function of seed and configuration and may go far faster than real
// time, so the link publishes after every frame, outside the task table (a FrameObserver, never
// judged against a budget), and every so many samples waits for the listening monitors'
// acknowledgements of the reliable topics: a monitor loses no FsmStatus of a simulated run, and the run computes exactly what it
// computes without one.
#include <cstdint>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "ringlet/executive/executive.hpp"
#include "ringlet/firmware/config.hpp"
#include "ringlet/remote/bridge.hpp"
#include "ringlet/whiteboard/whiteboard.hpp"

namespace ringlet::firmware {

class RemoteLink final : public executive::FrameObserver {
 public:
  /// Joins the DDS domain (throws ConfigError naming [remote] and DDS's reason). `machines`: the
  /// names a remote FsmControl may address. Refusals of remote writes are described on `log`.
  RemoteLink(const FirmwareConfig& config, const wb::Whiteboard& board, std::vector<std::string> machines,
             std::ostream& log);
  /// The observer that was there before (or null): it sees every frame first.
  void set_next(executive::FrameObserver* next) noexcept { next_ = next; }
  /// The remote writes accepted and the bridge's health, for the whiteboard task to deliver.
  [[nodiscard]] remote::Inbox* inbox() noexcept { return &bridge_->inbox(); }
  [[nodiscard]] remote::RequestCounts requests() const noexcept { return bridge_->request_totals(); }
  [[nodiscard]] std::chrono::nanoseconds cpu_time() const noexcept { return bridge_->cpu_time(); }
  [[nodiscard]] std::uint64_t pumps() const noexcept { return bridge_->pumps(); }
  ~RemoteLink() override;

  /// Before the first frame: waits for wait_for_monitors monitors (warning on `log` if they do not
  /// come), then starts the bridge thread on the real clock.
  void begin_run(std::ostream& log);
  /// After the last frame: everything posted is published (and, in lockstep, acknowledged).
  void end_run() noexcept;

  void frame_done(std::uint64_t frame, executive::Nanos frame_start) noexcept override;

  [[nodiscard]] remote::TypeCounts totals() const noexcept { return bridge_->totals(); }
  [[nodiscard]] remote::TypeCounts counts(wb::TypeId type) const noexcept { return bridge_->counts(type); }
  [[nodiscard]] const remote::BridgeConfig& bridge_config() const noexcept { return bridge_->config(); }
  /// Lockstep frames whose reliable samples were not all acknowledged in time.
  [[nodiscard]] std::uint64_t unacknowledged_frames() const noexcept { return unacknowledged_frames_; }

 private:
  std::unique_ptr<remote::Bridge> bridge_;
  executive::FrameObserver* next_ = nullptr;
  bool lockstep_;
  int wait_for_monitors_;
  double wait_timeout_s_;
  std::uint64_t unacknowledged_frames_ = 0;
  std::size_t written_since_flush_ = 0;
};

}  // namespace ringlet::firmware
