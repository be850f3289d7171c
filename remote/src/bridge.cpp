#include "ringlet/remote/bridge.hpp"

#include <algorithm>
#include <utility>

namespace ringlet::remote {
namespace {

// A request's own check beyond the value ranges from_sample enforces: "" when it may be applied.
template <class T>
std::string check_request(const T& /*msg*/, const BridgeConfig& /*config*/) {
  return {};
}
std::string check_request(const wb::FsmControl& c, const BridgeConfig& config) {
  const std::string_view name = c.machine.view();
  if (name.empty()) return "no machine named";
  if (config.machines.empty() || std::find(config.machines.begin(), config.machines.end(), name) != config.machines.end()) {
    return {};
  }
  std::string known;
  for (const auto& m : config.machines) known += (known.empty() ? "" : ", ") + m;
  return "no machine \"" + std::string(name) + "\" on this robot (" + known + ")";
}
std::string check_request(const wb::MissionGoals& g, const BridgeConfig& /*config*/) {
  if (g.count < 1 || g.count > g.x.size()) return "count must be 1 to " + std::to_string(g.x.size());
  if (!(g.tolerance > 0.0)) return "tolerance must be above 0";
  return {};
}

// The inbox carries the accepted remote writes and, when the bridge posts it, its own health.
std::array<bool, wb::kTypeCount> inbox_types(const BridgeConfig& config) {
  std::array<bool, wb::kTypeCount> types = config.accept;
  if (config.health_period.count() > 0) types[wb::kIndexOf<wb::BridgeHealth>] = true;
  return types;
}

}  // namespace

Bridge::Bridge(const wb::Whiteboard& board, BridgeConfig config)
    : board_(board),
      config_(std::move(config)),
      participant_(config_.domain),
      inbox_(inbox_types(config_), config_.inbox_capacity) {
  const bool remote_writes = std::any_of(config_.accept.begin(), config_.accept.end(), [](bool a) { return a; });
  wb::for_each_type([&]<class T>(std::type_identity<T>) {
    constexpr std::size_t i = wb::kIndexOf<T>;
    if (config_.types[i].publish) slots_[i].writer = participant_.writer<T>();
    // With remote writes on, every type's requests are read, so that the ones not allowed are
    // counted and described rather than left unheard.
    if (remote_writes) slots_[i].request_reader = participant_.request_reader<T>();
  });
}

Bridge::~Bridge() { stop(); }

void Bridge::start() {
  if (thread_.joinable()) return;
  stop_.store(false);
  thread_ = std::thread([this] {
    while (!stop_.load(std::memory_order_relaxed)) {
      pump();
      std::this_thread::sleep_for(config_.poll_period);
    }
  });
}

void Bridge::stop() noexcept {
  if (!thread_.joinable()) return;
  stop_.store(true);
  thread_.join();
  pump();
}

std::size_t Bridge::pump() noexcept { return pump(std::chrono::steady_clock::now().time_since_epoch()); }

std::size_t Bridge::pump(std::chrono::nanoseconds now) noexcept {
  const hal::Nanos cpu_start = stopwatch_.cpu_now();
  std::size_t written = 0;
  wb::for_each_type([&]<class T>(std::type_identity<T>) {
    written += pump_type<T>(now);
    take_requests<T>();
  });
  post_health(now);
  cpu_ns_.fetch_add((stopwatch_.cpu_now() - cpu_start).count(), std::memory_order_relaxed);
  pumps_.fetch_add(1, std::memory_order_relaxed);
  return written;
}

template <wb::Message T>
void Bridge::take_requests() noexcept {
  Slot& slot = slots_[wb::kIndexOf<T>];
  if (slot.request_reader == 0) return;
  constexpr int kBatch = 8;
  typename DdsType<T>::Sample samples[kBatch];
  void* ptrs[kBatch];
  dds_sample_info_t infos[kBatch];
  for (int i = 0; i < kBatch; ++i) ptrs[i] = &samples[i];
  for (dds_return_t n = kBatch; n == kBatch;) {
    n = dds_take(slot.request_reader, ptrs, infos, kBatch, kBatch);
    for (dds_return_t i = 0; i < n; ++i) {
      const auto& s = samples[i];
      if (!infos[i].valid_data || s.robot != config_.robot) continue;  // not for this robot
      if (!config_.accept[wb::kIndexOf<T>]) {
        slot.unauthorized.fetch_add(1, std::memory_order_relaxed);
        refuse(T::kName, s.generation, "remote writes of this type are not allowed ([remote] accept)");
        continue;
      }
      T msg{};
      if (!from_sample(s, msg)) {
        slot.malformed.fetch_add(1, std::memory_order_relaxed);
        refuse(T::kName, s.generation, "a value without whiteboard meaning (an unknown enum value, an unterminated string, NaN)");
        continue;
      }
      if (const std::string why = check_request(msg, config_); !why.empty()) {
        slot.malformed.fetch_add(1, std::memory_order_relaxed);
        refuse(T::kName, s.generation, why);
        continue;
      }
      if (inbox_.push(msg)) {
        slot.accepted.fetch_add(1, std::memory_order_relaxed);
      } else {
        slot.dropped.fetch_add(1, std::memory_order_relaxed);
        refuse(T::kName, s.generation, "the queue to the cycle is full");
      }
    }
  }
}

void Bridge::post_health(std::chrono::nanoseconds now) noexcept {
  if (config_.health_period.count() <= 0 || (last_health_ && now - *last_health_ < config_.health_period)) return;
  last_health_ = now;
  const TypeCounts c = totals();
  const RequestCounts r = request_totals();
  wb::BridgeHealth h;
  h.sent = c.sent;
  h.missed = c.missed;
  h.rate_skipped = c.rate_skipped;
  h.failed = c.failed;
  h.requests_accepted = r.accepted;
  h.requests_refused = r.unauthorized + r.malformed + r.dropped;
  h.monitors = matched(wb::kIndexOf<wb::FsmStatus>);
  h.pumps = pumps_.load(std::memory_order_relaxed);
  (void)inbox_.push(h);  // a full queue (nobody delivering) drops it; the next one says the same, newer
}

void Bridge::refuse(std::string_view type, std::uint64_t request, const std::string& why) noexcept {
  ++refusals_;
  if (config_.log == nullptr || (refusals_ > 20 && refusals_ % 100 != 0)) return;
  *config_.log << "remote: robot " << config_.robot << " refused " << type << " request #" << request << ": " << why
               << " (" << refusals_ << " refused so far)\n";
}

template <wb::Message T>
bool Bridge::write(Slot& slot, const T& msg, std::uint64_t generation) noexcept {
  typename DdsType<T>::Sample sample{};
  to_sample(msg, config_.robot, generation, sample);
  if (dds_write(slot.writer, &sample) < 0) {
    slot.failed.fetch_add(1, std::memory_order_relaxed);
    return false;
  }
  slot.sent.fetch_add(1, std::memory_order_relaxed);
  return true;
}

template <wb::Message T>
std::size_t Bridge::pump_type(std::chrono::nanoseconds now) noexcept {
  Slot& slot = slots_[wb::kIndexOf<T>];
  if (slot.writer == 0) return 0;
  const std::uint64_t newest = board_.generation<T>();
  if (newest <= slot.last) return 0;
  const auto period = config_.types[wb::kIndexOf<T>].min_period;
  std::size_t written = 0;
  if (period.count() > 0) {
    // Rate-limited: the newest generation once per period; the ones before it are skipped.
    if (slot.last_sent && now - *slot.last_sent < period) return 0;
    const wb::ReadResult<T> r = board_.read<T>(newest);
    if (r.ok()) {
      slot.rate_skipped.fetch_add(newest - slot.last - 1, std::memory_order_relaxed);
      written += write(slot, r.msg, newest) ? 1U : 0U;
      slot.last_sent = now;
    } else {
      slot.missed.fetch_add(newest - slot.last, std::memory_order_relaxed);
    }
    slot.last = newest;
    return written;
  }
  // Every generation, oldest first; what the ring no longer holds is counted and skipped.
  std::uint64_t g = slot.last + 1;
  while (g <= newest) {
    const wb::ReadResult<T> r = board_.read<T>(g);
    if (r.status == wb::ReadStatus::kMissed) {
      const std::uint64_t lost = std::max<std::uint64_t>(r.missed, 1);
      slot.missed.fetch_add(lost, std::memory_order_relaxed);
      g += lost;
      continue;
    }
    if (!r.ok()) break;  // kNotYet: a writer is mid-post; the next pass gets it
    written += write(slot, r.msg, g) ? 1U : 0U;
    slot.last = g;
    ++g;
  }
  slot.last = std::max(slot.last, std::min(g - 1, newest));
  if (written > 0) slot.last_sent = now;
  return written;
}

bool Bridge::flush(std::chrono::milliseconds timeout) noexcept {
  const dds_time_t deadline =
      dds_time() + static_cast<dds_duration_t>(std::chrono::duration_cast<std::chrono::nanoseconds>(timeout).count());
  bool all = true;
  wb::for_each_type([&]<class T>(std::type_identity<T>) {
    const Slot& slot = slots_[wb::kIndexOf<T>];
    if (slot.writer == 0 || topic_qos(T::kId).kind == TopicKind::kTelemetry) return;
    const dds_duration_t left = std::max<dds_duration_t>(deadline - dds_time(), 0);
    all = dds_wait_for_acks(slot.writer, left) == DDS_RETCODE_OK && all;
  });
  return all;
}

std::uint32_t Bridge::matched(std::size_t index) const noexcept {
  const Slot& slot = slots_[index];
  if (slot.writer == 0) return 0;
  dds_publication_matched_status_t st{};
  if (dds_get_publication_matched_status(slot.writer, &st) < 0) return 0;
  return st.current_count;
}

TypeCounts Bridge::counts(wb::TypeId type) const noexcept {
  const Slot* s = slot_of(type);
  if (s == nullptr) return {};
  return {s->sent.load(std::memory_order_relaxed), s->missed.load(std::memory_order_relaxed),
          s->rate_skipped.load(std::memory_order_relaxed), s->failed.load(std::memory_order_relaxed)};
}

const Bridge::Slot* Bridge::slot_of(wb::TypeId type) const noexcept {
  for (std::size_t i = 0; i < wb::kTypeCount; ++i) {
    if (wb::kTypes[i].id == type) return &slots_[i];
  }
  return nullptr;
}

RequestCounts Bridge::requests(wb::TypeId type) const noexcept {
  const Slot* s = slot_of(type);
  if (s == nullptr) return {};
  return {s->accepted.load(std::memory_order_relaxed), s->unauthorized.load(std::memory_order_relaxed),
          s->malformed.load(std::memory_order_relaxed), s->dropped.load(std::memory_order_relaxed)};
}

RequestCounts Bridge::request_totals() const noexcept {
  RequestCounts t;
  for (const auto& info : wb::kTypes) t += requests(info.id);
  return t;
}

TypeCounts Bridge::totals() const noexcept {
  TypeCounts t;
  for (const auto& info : wb::kTypes) t += counts(info.id);
  return t;
}

}  // namespace ringlet::remote
