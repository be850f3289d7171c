#include "ringlet/firmware/remote_link.hpp"

#include <chrono>
#include <thread>

#include "ringlet/hal/read_file.hpp"

namespace ringlet::firmware {
namespace {

// Longest a lockstep frame waits for the monitors' acknowledgements: a monitor that stopped
// listening without leaving (a killed process) is dropped by DDS after its lease; until then the
// run goes on at this pace, counting the frames.
constexpr std::chrono::milliseconds kFlushTimeout{2000};
// Samples written between two waits for the acknowledgements in lockstep (below the FsmStatus
// writer's depth of 256 per instance).
constexpr std::size_t kFlushEvery = 128;

remote::BridgeConfig make_bridge_config(const FirmwareConfig& config, std::vector<std::string> machines,
                                        std::ostream& log) {
  const RemoteSettings& r = config.remote;
  remote::BridgeConfig b;
  b.robot = static_cast<std::uint16_t>(r.robot);
  b.domain.id = static_cast<std::uint32_t>(r.domain);
  b.domain.partition = r.partition;
  if (!r.cyclone_config.empty()) {
    const hal::FileRead file = hal::read_file(r.cyclone_config, "Cyclone DDS configuration");
    if (!file.ok()) throw ConfigError(config.positions.at("remote.cyclone_config") + ": remote.cyclone_config: " + file.error);
    b.domain.cyclone_config = file.bytes;
  }
  b.poll_period = std::chrono::milliseconds{r.poll_ms};
  for (std::size_t i = 0; i < wb::kTypeCount; ++i) {
    const std::string_view name = wb::kTypes[i].name;
    if (const auto it = r.max_rate_hz.find(name); it != r.max_rate_hz.end()) {
      b.types[i].min_period = std::chrono::nanoseconds{static_cast<std::int64_t>(1e9 / it->second)};
    }
    for (const auto& u : r.unpublished) b.types[i].publish = b.types[i].publish && u != name;
    for (const auto& a : r.accept) b.accept[i] = b.accept[i] || a == name;
  }
  b.machines = std::move(machines);
  b.log = &log;
  return b;
}

}  // namespace

RemoteLink::RemoteLink(const FirmwareConfig& config, const wb::Whiteboard& board, std::vector<std::string> machines,
                       std::ostream& log)
    : lockstep_(config.clock == ClockMode::kLockstep),
      wait_for_monitors_(config.remote.wait_for_monitors),
      wait_timeout_s_(config.remote.wait_timeout_s) {
  try {
    bridge_ = std::make_unique<remote::Bridge>(board, make_bridge_config(config, std::move(machines), log));
  } catch (const remote::RemoteError& e) {
    throw ConfigError(config.positions.at("remote") + ": remote: " + e.what());
  }
}

RemoteLink::~RemoteLink() { end_run(); }

void RemoteLink::begin_run(std::ostream& log) {
  if (wait_for_monitors_ > 0) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(wait_timeout_s_);
    while (bridge_->matched_readers<wb::FsmStatus>() < static_cast<std::uint32_t>(wait_for_monitors_) &&
           std::chrono::steady_clock::now() < end) {
      std::this_thread::sleep_for(std::chrono::milliseconds{5});
    }
    const std::uint32_t found = bridge_->matched_readers<wb::FsmStatus>();
    if (found < static_cast<std::uint32_t>(wait_for_monitors_)) {
      log << "ringlet: warning: remote: " << found << " of " << wait_for_monitors_ << " monitors after "
          << wait_timeout_s_ << " s (DDS domain " << bridge_->config().domain.id << ", partition \""
          << bridge_->config().domain.partition << "\"); running anyway\n";
    }
  }
  if (!lockstep_) bridge_->start();
}

void RemoteLink::end_run() noexcept {
  if (bridge_->running()) {
    bridge_->stop();
  } else {
    bridge_->pump();
  }
  (void)bridge_->flush(kFlushTimeout);
}

void RemoteLink::frame_done(std::uint64_t frame, executive::Nanos frame_start) noexcept {
  if (next_ != nullptr) next_->frame_done(frame, frame_start);
  if (!lockstep_) return;
  // Waiting for the acknowledgements after every frame would pace the run on DDS's heartbeats
  // (100 ms); every kFlushEvery samples keeps each instance's unacknowledged samples far below the
  // depth the writer keeps (remote::topic_qos), so nothing is dropped before the monitor has it.
  written_since_flush_ += bridge_->pump(frame_start);  // rate limits on the virtual clock
  if (written_since_flush_ >= kFlushEvery) {
    if (!bridge_->flush(kFlushTimeout)) ++unacknowledged_frames_;
    written_since_flush_ = 0;
  }
}

}  // namespace ringlet::firmware
