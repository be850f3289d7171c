// ringlet-monitor serve: the live page. Everything the robots publish is gathered here (per
// robot: the newest sample of each type, every machine's state and its recent transitions, the
// trajectory, the cells the planner marked occupied) and served over HTTP (Debian's cpp-httplib):
//   /                 the page (page/index.html, app.js, style.css, compiled in)
//   /machines/*.svg   the shipped machines' diagrams (docs/machines, compiled in)
//   /api/machines     the diagrams' paths
//   /api/robots       the robots heard: id, seconds since last heard, samples
//   /api/state?robot=N    one robot's view as JSON (N omitted: the lowest id heard)
//   /events?robot=N   the same view as server-sent events, five times a second
// The gathering runs on the main thread; the HTTP server on its own threads; they share the view
// under a mutex (nothing here is on a robot's cycle).
#include <httplib.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <iostream>
#include <map>
#include <mutex>
#include <set>
#include <thread>

#include "monitor_common.hpp"
#include "page_assets.hpp"

namespace ringlet::monitor {
namespace {

constexpr std::size_t kTransitionsPerMachine = 10;  // so a busy machine does not hide the others' changes
constexpr std::size_t kTrajectoryPoints = 4000;  // beyond this, every other point is dropped
constexpr std::size_t kCellsKept = 20000;
constexpr double kTrajectoryStep = 0.02;  // m between trajectory points
constexpr auto kEventPeriod = std::chrono::milliseconds{200};

struct RobotView {
  Clock::time_point heard{};
  std::uint64_t samples = 0;
  std::map<std::string, nlohmann::json> latest;    // type name -> {"generation", "fields"}
  std::map<std::string, nlohmann::json> machines;  // machine -> FsmStatus fields
  std::map<std::string, std::deque<nlohmann::json>> transitions;  // machine -> its latest, oldest first
  std::uint64_t transition_count = 0;
  std::vector<std::array<double, 2>> trajectory;
  std::set<std::uint32_t> cells;
};

class LiveView {
 public:
  template <wb::Message T>
  void add(std::uint16_t robot, std::uint64_t generation, const T& m) {
    nlohmann::json fields = fields_json(m);
    const std::lock_guard lock(mutex_);
    RobotView& v = robots_[robot];
    v.heard = Clock::now();
    ++v.samples;
    if constexpr (std::is_same_v<T, wb::FsmStatus>) note_state(v, m, fields);
    if constexpr (std::is_same_v<T, wb::Pose>) note_pose(v, m);
    if constexpr (std::is_same_v<T, wb::Plan>) {
      for (std::size_t i = 0; i < std::min<std::size_t>(m.new_cell_count, m.new_cells.size()) && v.cells.size() < kCellsKept; ++i) {
        v.cells.insert(m.new_cells[i]);
      }
      fields.erase("new_cells");  // gathered in `cells`
    }
    v.latest[std::string(T::kName)] = {{"generation", generation}, {"fields", std::move(fields)}};
  }

  nlohmann::json robots() const {
    const std::lock_guard lock(mutex_);
    return robots_json(Clock::now());
  }

  /// One robot's view (the lowest id when `robot` is empty); null when none has been heard.
  nlohmann::json state(std::optional<int> robot) const {
    const std::lock_guard lock(mutex_);
    const auto now = Clock::now();
    auto it = robot ? robots_.find(*robot) : robots_.begin();
    if (it == robots_.end()) return {{"robot", nullptr}, {"robots", robots_json(now)}};
    const RobotView& v = it->second;
    nlohmann::json machines = nlohmann::json::array();
    for (const auto& [name, fields] : v.machines) machines.push_back(fields);
    nlohmann::json trajectory = nlohmann::json::array();
    for (const auto& p : v.trajectory) trajectory.push_back({p[0], p[1]});
    std::vector<nlohmann::json> changes;
    for (const auto& [machine, list] : v.transitions) changes.insert(changes.end(), list.begin(), list.end());
    std::sort(changes.begin(), changes.end(), [](const auto& a, const auto& b) { return a["n"] < b["n"]; });
    return {{"robot", it->first},
            {"robots", robots_json(now)},
            {"age_s", std::chrono::duration<double>(now - v.heard).count()},
            {"samples", v.samples},
            {"types", v.latest},
            {"machines", machines},
            {"transitions", changes},
            {"trajectory", trajectory},
            {"cells", v.cells}};
  }

 private:
  void note_state(RobotView& v, const wb::FsmStatus& s, const nlohmann::json& fields) {
    const std::string machine(s.machine.view());
    const auto it = v.machines.find(machine);
    const std::string before = it != v.machines.end() ? it->second["state"].get<std::string>() : std::string(s.previous.view());
    if (!before.empty() && before != s.state.view()) {
      auto& list = v.transitions[machine];
      list.push_back({{"n", ++v.transition_count},
                      {"t", std::chrono::duration<double>(Clock::now() - start_).count()},
                      {"machine", machine},
                      {"from", before},
                      {"to", std::string(s.state.view())},
                      {"ringlets", s.ringlets}});
      if (list.size() > kTransitionsPerMachine) list.pop_front();
    }
    v.machines[machine] = fields;
  }
  static void note_pose(RobotView& v, const wb::Pose& p) {
    if (!p.valid || !std::isfinite(p.x) || !std::isfinite(p.y)) return;
    if (!v.trajectory.empty() && std::hypot(p.x - v.trajectory.back()[0], p.y - v.trajectory.back()[1]) < kTrajectoryStep) return;
    if (v.trajectory.size() >= kTrajectoryPoints) {
      for (std::size_t i = 0; i < v.trajectory.size() / 2; ++i) v.trajectory[i] = v.trajectory[2 * i];
      v.trajectory.resize(v.trajectory.size() / 2);
    }
    v.trajectory.push_back({p.x, p.y});
  }
  nlohmann::json robots_json(Clock::time_point now) const {
    nlohmann::json list = nlohmann::json::array();
    for (const auto& [id, v] : robots_) {
      list.push_back({{"robot", id}, {"age_s", std::chrono::duration<double>(now - v.heard).count()}, {"samples", v.samples}});
    }
    return list;
  }

  mutable std::mutex mutex_;
  std::map<int, RobotView> robots_;
  Clock::time_point start_ = Clock::now();
};

std::optional<int> robot_param(const httplib::Request& req) {
  if (!req.has_param("robot")) return std::nullopt;
  const std::string text = req.get_param_value("robot");
  char* end = nullptr;
  const long id = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || id < 0 || id > 65535) return -1;  // matches no robot
  return static_cast<int>(id);
}

}  // namespace

int serve(const Options& o, const ServeOptions& so) {
  Tap tap(o);
  LiveView view;
  httplib::Server server;
  for (const PageAsset& a : page_assets()) {
    server.Get(std::string(a.path), [a](const httplib::Request&, httplib::Response& res) {
      res.set_content(a.bytes.data(), a.bytes.size(), std::string(a.mime).c_str());
    });
  }
  server.Get("/api/machines", [](const httplib::Request&, httplib::Response& res) {
    nlohmann::json list = nlohmann::json::array();
    for (const PageAsset& a : page_assets()) {
      if (a.path.starts_with("/machines/")) list.push_back(std::string(a.path));
    }
    res.set_content(list.dump(), "application/json");
  });
  server.Get("/api/robots", [&view](const httplib::Request&, httplib::Response& res) {
    res.set_content(view.robots().dump(), "application/json");
  });
  server.Get("/api/state", [&view](const httplib::Request& req, httplib::Response& res) {
    res.set_content(view.state(robot_param(req)).dump(), "application/json");
  });
  server.Get("/events", [&view](const httplib::Request& req, httplib::Response& res) {
    const std::optional<int> robot = robot_param(req);
    res.set_header("Cache-Control", "no-cache");
    res.set_chunked_content_provider("text/event-stream", [&view, robot](std::size_t, httplib::DataSink& sink) {
      const std::string event = "data: " + view.state(robot).dump() + "\n\n";
      if (!sink.write(event.data(), event.size())) return false;
      std::this_thread::sleep_for(kEventPeriod);
      return !g_stop.load();
    });
  });

  const int port = so.port == 0 ? server.bind_to_any_port(so.bind) : (server.bind_to_port(so.bind, so.port) ? so.port : -1);
  if (port < 0) {
    std::cerr << "ringlet-monitor: serve: cannot listen on " << so.bind << ":" << so.port
              << " (in use, or not an address of this machine)\n";
    return 2;
  }
  std::thread http([&server] { server.listen_after_bind(); });
  std::cout << "serving the live page at http://" << (so.bind == "0.0.0.0" ? std::string("127.0.0.1") : so.bind) << ":"
            << port << "/ (listening on " << network_text(o) << "; Ctrl-C ends)" << std::endl;
  auto last_heard = Clock::now();
  bool warned = false;
  while (!g_stop.load()) {
    bool heard = false;
    tap.poll([&]<class T>(std::uint16_t robot, std::uint64_t gen, const T& m) {
      view.add(robot, gen, m);
      heard = true;
    });
    const auto now = Clock::now();
    if (heard) last_heard = now;
    if (!warned && now - last_heard > std::chrono::seconds{10}) {
      std::cerr << "serve: no robot heard for 10 s on " << network_text(o) << "\n";
      warned = true;
    }
    if (heard) warned = false;
    std::this_thread::sleep_for(std::chrono::milliseconds{10});
  }
  server.stop();
  http.join();
  return 0;
}

}  // namespace ringlet::monitor
