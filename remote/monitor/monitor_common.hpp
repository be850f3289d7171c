#pragma once
// What every ringlet-monitor command shares: the options that say where to listen, samples as
// JSON, and the Tap, which hears every whiteboard type on one participant (list, serve, record and
// the PlotJuggler stream are all fed by it).
#include <nlohmann/json.hpp>

#include <array>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "ringlet/hal/read_file.hpp"
#include "ringlet/remote/domain.hpp"
#include "ringlet/whiteboard/messages.hpp"

namespace ringlet::monitor {

using Clock = std::chrono::steady_clock;

/// Set by SIGINT / SIGTERM: every loop ends at the next turn.
extern std::atomic<bool> g_stop;

struct Options {
  int domain = 0;
  std::string partition = "ringlet";
  std::string config;  // Cyclone DDS XML file
  double wait_s = 2.0;
  std::optional<int> robot;
  bool json = false;
  long count = 0;  // echo: stop after this many (0: until interrupted or --wait ends)
  bool once = false;
  std::string type;
};

/// "DDS domain 0, partition "ringlet", loopback only (...)": for messages about what was heard.
std::string network_text(const Options& o);
/// The domain to join (reads --config; throws remote::RemoteError naming the file).
remote::DomainConfig domain_of(const Options& o);

// ---- samples as JSON ---------------------------------------------------------------------------
/// Enums as their schema names, strings as text, arrays as arrays; `numeric_enums` gives enums as
/// numbers (for plotting tools, which ignore text).
template <class V>
nlohmann::json to_json(const V& v, bool numeric_enums = false) {
  if constexpr (wb::SchemaEnum<V>) {
    if (!numeric_enums) {
      for (const auto& e : wb::EnumTraits<V>::kEntries) {
        if (e.value == v) return std::string(e.text);
      }
    }
    return static_cast<long long>(v);
  } else if constexpr (std::is_same_v<V, bool> || std::is_arithmetic_v<V>) {
    return v;
  } else if constexpr (requires { v.view(); }) {
    return std::string(v.view());
  } else {
    nlohmann::json a = nlohmann::json::array();
    for (const auto& e : v) a.push_back(to_json(e, numeric_enums));
    return a;
  }
}

template <wb::Message T>
nlohmann::json fields_json(const T& m, bool numeric_enums = false) {
  nlohmann::json fields = nlohmann::json::object();
  visit_fields(m, [&](std::string_view name, const auto& value) { fields[std::string(name)] = to_json(value, numeric_enums); });
  return fields;
}

template <wb::Message T>
nlohmann::json message_json(const T& m, std::uint16_t robot, std::uint64_t generation) {
  return {{"type", std::string(T::kName)}, {"robot", robot}, {"generation", generation}, {"fields", fields_json(m)}};
}

/// Takes everything the reader holds; calls f(robot, generation, message) for each valid sample
/// (samples that do not validate are counted in `invalid` and skipped).
template <wb::Message T, class F>
void take_all(dds_entity_t reader, std::uint64_t& invalid, F&& f) {
  constexpr int kBatch = 32;
  static std::vector<typename remote::DdsType<T>::Sample> buf(kBatch);
  void* ptrs[kBatch];
  dds_sample_info_t infos[kBatch];
  for (int i = 0; i < kBatch; ++i) ptrs[i] = &buf[static_cast<std::size_t>(i)];
  for (dds_return_t n = kBatch; n == kBatch;) {
    n = dds_take(reader, ptrs, infos, kBatch, kBatch);
    for (dds_return_t i = 0; i < n; ++i) {
      if (!infos[i].valid_data) continue;
      const auto& s = buf[static_cast<std::size_t>(i)];
      T m;
      if (!remote::from_sample(s, m)) {
        ++invalid;
        continue;
      }
      f(s.robot, s.generation, m);
    }
  }
}

/// Every whiteboard type's reader on one participant, each keeping all it receives until taken;
/// the state topics (transient-local) bring a robot's current states at once.
class Tap {
 public:
  explicit Tap(const Options& o) : participant_(domain_of(o)), robot_(o.robot) {
    wb::for_each_type([&]<class T>(std::type_identity<T>) { readers_[wb::kIndexOf<T>] = participant_.reader<T>(true); });
  }
  /// Takes every sample waiting, of every type in id order: f(robot, generation, const T&) for
  /// those of the chosen robot (--robot), or of all.
  template <class F>
  void poll(F&& f) {
    wb::for_each_type([&]<class T>(std::type_identity<T>) {
      take_all<T>(readers_[wb::kIndexOf<T>], invalid_, [&](std::uint16_t robot, std::uint64_t gen, const T& m) {
        if (!robot_ || *robot_ == robot) f(robot, gen, m);
      });
    });
  }
  /// Samples refused: values without whiteboard meaning.
  [[nodiscard]] std::uint64_t invalid() const noexcept { return invalid_; }
  [[nodiscard]] remote::Participant& participant() noexcept { return participant_; }

 private:
  remote::Participant participant_;
  std::array<dds_entity_t, wb::kTypeCount> readers_{};
  std::optional<int> robot_;
  std::uint64_t invalid_ = 0;
};

// ---- the commands beyond ringlet_monitor.cpp's own ----------------------------------------------
struct ServeOptions {
  std::string bind = "127.0.0.1";
  int port = 8080;  // 0: any free port (printed)
};
/// The live page: http://bind:port/ until Ctrl-C. Exit 2 when the port cannot be bound.
int serve(const Options& o, const ServeOptions& s);

/// Writes every sample heard to `file` (record format: remote/README.md) until Ctrl-C, --wait
/// seconds (when given) or --count samples.
int record(const Options& o, const std::string& file, bool wait_given);
/// Publishes a recording again, as the robots did, at `speed` times the recorded pace.
int replay(const Options& o, const std::string& file, double speed);

/// Streams every sample heard as JSON over UDP to PlotJuggler's UDP server ("host:port").
int plotjuggler(const Options& o, const std::string& target, bool wait_given);

}  // namespace ringlet::monitor
