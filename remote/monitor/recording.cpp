// ringlet-monitor record / replay: what the robots published, kept in a file and published again.
//
// The file is JSON lines (remote/README.md, "Recordings"):
//   line 1   {"ringlet_record":1, "domain":D, "partition":P, "types":[{"type":"Pose","version":1},...]}
//   then     {"t":S, "robot":R, "type":"Pose", "generation":G, "text":"x=..., ...", "fields":{...}}
// t: seconds since the recording began (non-decreasing); text: the whiteboard's text form of the
// message (description(), which from_string reads back exactly; replay uses it); fields: the same
// values as JSON, for people and tools such as jq (replay ignores them).
// Replay reads and checks the whole file before it publishes anything: a bad line is named
// (FILE:LINE: why) and nothing goes out.
#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <thread>
#include <variant>

#include "monitor_common.hpp"

namespace ringlet::monitor {
namespace {

constexpr int kFormat = 1;
constexpr std::size_t kAckEvery = 128;

nlohmann::json header_json(const Options& o) {
  nlohmann::json types = nlohmann::json::array();
  for (const auto& t : wb::kTypes) types.push_back({{"type", std::string(t.name)}, {"version", t.version}});
  return {{"ringlet_record", kFormat}, {"domain", o.domain}, {"partition", o.partition}, {"types", types}};
}

// One recorded sample, checked and ready to publish.
template <class L>
struct VariantOf;
template <class... Ts>
struct VariantOf<wb::TypeList<Ts...>> {
  using type = std::variant<Ts...>;
};
using Message = VariantOf<wb::AllMessages>::type;

struct Recorded {
  double t = 0.0;
  std::uint16_t robot = 0;
  std::uint64_t generation = 0;
  Message msg;
};

// Reads FILE whole; "" and the samples, or the first problem as FILE:LINE: why.
std::string load(const std::string& file, std::vector<Recorded>& out) {
  std::ifstream in(file);
  if (!in) return file + ": cannot open: " + std::strerror(errno);
  std::string line;
  long number = 0;
  const auto at = [&](const std::string& why) { return file + ":" + std::to_string(number) + ": " + why; };
  double last_t = 0.0;
  while (std::getline(in, line)) {
    ++number;
    if (line.empty()) continue;
    const nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
    if (j.is_discarded() || !j.is_object()) return at("not a JSON object");
    if (number == 1) {
      if (!j.contains("ringlet_record") || j["ringlet_record"] != kFormat) {
        return at("not a ringlet-monitor recording (the first line must be {\"ringlet_record\":1, ...})");
      }
      if (!j.contains("types") || !j["types"].is_array()) return at("the header has no \"types\" list");
      for (const auto& t : j["types"]) {
        if (!t.is_object() || !t.contains("type") || !t["type"].is_string() || !t.contains("version")) {
          return at("a \"types\" entry needs \"type\" and \"version\"");
        }
        const auto info = wb::find_type(t["type"].get<std::string>());
        if (info && t["version"] != info->version) {
          return at("recorded with " + t["type"].get<std::string>() + " version " + t["version"].dump() +
                    ", this build has version " + std::to_string(info->version));
        }
      }
      continue;
    }
    for (const char* key : {"t", "robot", "type", "generation", "text"}) {
      if (!j.contains(key)) return at(std::string("no \"") + key + "\"");
    }
    if (!j["t"].is_number() || !(j["t"].get<double>() >= last_t)) return at("\"t\" must be a number, not below the line before's");
    if (!j["robot"].is_number_unsigned() || j["robot"].get<std::uint64_t>() > 65535) return at("\"robot\" must be 0 to 65535");
    if (!j["generation"].is_number_unsigned()) return at("\"generation\" must be a whole number");
    if (!j["type"].is_string() || !j["text"].is_string()) return at("\"type\" and \"text\" must be strings");
    Recorded r;
    r.t = last_t = j["t"].get<double>();
    r.robot = static_cast<std::uint16_t>(j["robot"].get<std::uint64_t>());
    r.generation = j["generation"].get<std::uint64_t>();
    const std::string type = j["type"].get<std::string>();
    const std::string text = j["text"].get<std::string>();
    std::string error = "no whiteboard type \"" + type + "\"";
    wb::for_each_type([&]<class T>(std::type_identity<T>) {
      if (T::kName != type) return;
      auto parsed = T::from_string(text);
      if (parsed) {
        r.msg = *parsed;
        error.clear();
      } else {
        error = type + ": " + parsed.error();
      }
    });
    if (!error.empty()) return at(error);
    out.push_back(std::move(r));
  }
  if (number == 0) return file + ": empty (not a recording)";
  return {};
}

}  // namespace

int record(const Options& o, const std::string& file, bool wait_given) {
  Tap tap(o);
  std::ofstream out(file, std::ios::trunc);
  if (!out) {
    std::cerr << "ringlet-monitor: record: cannot write " << file << ": " << std::strerror(errno) << "\n";
    return 2;
  }
  out << header_json(o).dump() << '\n';
  const auto start = Clock::now();
  long samples = 0;
  std::set<int> robots;
  auto next_progress = start + std::chrono::seconds{5};
  while (!g_stop.load() && (o.count == 0 || samples < o.count) &&
         (!wait_given || Clock::now() - start < std::chrono::duration<double>(o.wait_s))) {
    tap.poll([&]<class T>(std::uint16_t robot, std::uint64_t gen, const T& m) {
      if (o.count > 0 && samples >= o.count) return;
      const double t = std::chrono::duration<double>(Clock::now() - start).count();
      nlohmann::json j = {{"t", t}, {"robot", robot}, {"type", std::string(T::kName)}, {"generation", gen},
                          {"text", m.description()}, {"fields", fields_json(m)}};
      out << j.dump() << '\n';
      ++samples;
      robots.insert(robot);
    });
    if (Clock::now() >= next_progress) {
      std::cerr << "record: " << samples << " samples of " << robots.size() << " robots\n";
      next_progress += std::chrono::seconds{5};
    }
    std::this_thread::sleep_for(std::chrono::milliseconds{5});
  }
  out.flush();
  if (!out) {
    std::cerr << "ringlet-monitor: record: writing " << file << " failed (disk full?)\n";
    return 2;
  }
  if (samples == 0) {
    std::cerr << "ringlet-monitor: record: nothing heard on " << network_text(o) << " (" << file << " holds only the header)\n";
    return 1;
  }
  std::cout << "recorded " << samples << " samples of " << robots.size() << " robot" << (robots.size() == 1 ? "" : "s")
            << " to " << file << "\n";
  return 0;
}

int replay(const Options& o, const std::string& file, double speed) {
  std::vector<Recorded> samples;
  if (const std::string error = load(file, samples); !error.empty()) {
    std::cerr << "ringlet-monitor: replay: " << error << "\n";
    return 2;
  }
  remote::Participant p(domain_of(o));
  std::array<dds_entity_t, wb::kTypeCount> writers{};
  wb::for_each_type([&]<class T>(std::type_identity<T>) { writers[wb::kIndexOf<T>] = p.writer<T>(); });
  // Give monitors a moment to find the writers (--wait at most), so the first samples reach them.
  const auto wait_end = Clock::now() + std::chrono::duration<double>(o.wait_s);
  dds_publication_matched_status_t matched{};
  while (!g_stop.load() && Clock::now() < wait_end &&
         (dds_get_publication_matched_status(writers[wb::kIndexOf<wb::FsmStatus>], &matched) < 0 || matched.current_count == 0)) {
    std::this_thread::sleep_for(std::chrono::milliseconds{5});
  }
  const auto start = Clock::now();
  std::size_t sent = 0;
  std::set<int> robots;
  for (const Recorded& r : samples) {
    if (g_stop.load()) break;
    if (speed > 0.0) std::this_thread::sleep_until(start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(r.t / speed)));
    std::visit(
        [&]<class T>(const T& m) {
          typename remote::DdsType<T>::Sample s{};
          remote::to_sample(m, r.robot, r.generation, s);
          if (dds_write(writers[wb::kIndexOf<T>], &s) >= 0) ++sent;
        },
        r.msg);
    robots.insert(r.robot);
    // As the firmware's lockstep link does: every so many samples, wait until the listening
    // monitors have acknowledged the reliable ones, so a fast replay overruns no writer's history.
    if (sent % kAckEvery == 0) {
      for (const dds_entity_t w : writers) (void)dds_wait_for_acks(w, DDS_SECS(2));
    }
  }
  for (const dds_entity_t w : writers) (void)dds_wait_for_acks(w, DDS_SECS(5));
  std::cout << "replayed " << sent << " of " << samples.size() << " samples of " << robots.size() << " robot"
            << (robots.size() == 1 ? "" : "s") << " from " << file << "\n";
  return sent == samples.size() ? 0 : 1;
}

}  // namespace ringlet::monitor
