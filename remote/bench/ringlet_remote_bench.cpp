// ringlet-remote-bench: what a monitor on this machine gets from a robot's bridge, over loopback.
//
//   latency  a robot process posts a Pose every millisecond, stamped with the monotonic clock
//            (shared by both processes); the monitor process measures post -> received, p50 / p99
//   rate     the robot posts FsmStatus at each --rates rate for --seconds; the monitor counts the
//            generations it received: the highest rate with none lost is the sustained rate
//   ddsperf  the same loopback configuration, `ddsperf ping` / `ddsperf pong` (Cyclone DDS's own
//            tool): its one-way latency (round trip / 2) is the floor the bridge adds to
//
// Exit codes: 0 measured · 1 a measurement failed (no match, the robot process failed) · 2 bad flags.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <optional>
#include <regex>
#include <string>
#include <thread>
#include <vector>

#include "ringlet/remote/bridge.hpp"

extern char** environ;

namespace {

using namespace ringlet;
using Clock = std::chrono::steady_clock;
using namespace std::chrono_literals;

struct Options {
  double seconds = 3.0;
  std::vector<double> rates{500, 1000, 2000, 5000};
  int poll_us = 2000;
  std::size_t depth = 8;
  bool ddsperf = true;
  std::string json;
};

double now_us(Clock::time_point epoch) { return std::chrono::duration<double, std::micro>(Clock::now() - epoch).count(); }

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<std::size_t>(q * static_cast<double>(v.size())))];
}

remote::DomainConfig bench_domain(const std::string& what) {
  return {0, "ringlet-bench-" + std::to_string(::getpid()) + "-" + what, ""};
}

// The robot side, in a child process: a whiteboard of `depth` generations and a bridge polling
// every poll_us, once a monitor reads FsmStatus; `post(i)` is called at `hz` for `seconds`.
template <class Post>
pid_t robot_process(const remote::DomainConfig& domain, const Options& o, double hz, Post post) {
  const pid_t child = ::fork();
  if (child != 0) return child;
  int rc = 1;
  try {
    wb::Whiteboard board(o.depth);
    remote::BridgeConfig config;
    config.robot = 1;
    config.domain = domain;
    config.poll_period = std::chrono::microseconds{o.poll_us};
    remote::Bridge bridge(board, config);
    const auto end_wait = Clock::now() + 20s;
    while (bridge.matched_readers<wb::FsmStatus>() == 0 && Clock::now() < end_wait) std::this_thread::sleep_for(1ms);
    if (bridge.matched_readers<wb::FsmStatus>() > 0) {
      std::this_thread::sleep_for(200ms);  // the other topics' readers match too
      bridge.start();
      const auto start = Clock::now();
      const auto period = std::chrono::duration<double>(1.0 / hz);
      const auto n = static_cast<std::uint64_t>(o.seconds * hz);
      for (std::uint64_t i = 1; i <= n; ++i) {
        std::this_thread::sleep_until(start + std::chrono::duration_cast<Clock::duration>(period * static_cast<double>(i)));
        post(board, i);
      }
      bridge.stop();
      (void)bridge.flush(5000ms);
      rc = 0;
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ringlet-remote-bench: robot process: %s\n", e.what());
  }
  ::_exit(rc);
}

// Takes every sample of T from `reader` until `done` says so or `timeout` passes.
template <wb::Message T, class OnSample, class Done>
void receive(dds_entity_t reader, std::chrono::milliseconds timeout, OnSample on_sample, Done done) {
  const dds_entity_t ws = dds_create_waitset(DDS_CYCLONEDDS_HANDLE);
  const dds_entity_t cond = dds_create_readcondition(reader, DDS_ANY_STATE);
  dds_waitset_attach(ws, cond, 0);
  std::vector<typename remote::DdsType<T>::Sample> buf(64);
  void* ptrs[64];
  dds_sample_info_t infos[64];
  for (std::size_t i = 0; i < buf.size(); ++i) ptrs[i] = &buf[i];
  const auto end = Clock::now() + timeout;
  while (!done() && Clock::now() < end) {
    (void)dds_waitset_wait(ws, nullptr, 0, DDS_MSECS(50));
    for (dds_return_t n = 64; n == 64;) {
      n = dds_take(reader, ptrs, infos, 64, 64);
      for (dds_return_t i = 0; i < n; ++i) {
        if (infos[i].valid_data) on_sample(buf[static_cast<std::size_t>(i)]);
      }
    }
  }
  dds_delete(cond);
  dds_delete(ws);
}

struct Latency {
  std::size_t samples = 0;
  std::size_t posted = 0;
  double p50_us = 0, p99_us = 0, mean_us = 0, max_us = 0;
};

std::optional<Latency> measure_latency(const Options& o) {
  const auto domain = bench_domain("latency");
  const auto epoch = Clock::now();
  const double hz = 1000.0;
  const pid_t child = robot_process(domain, o, hz, [epoch](wb::Whiteboard& board, std::uint64_t) {
    wb::Pose p;
    p.x = now_us(epoch);  // the monotonic clock is the machine's: both processes read the same
    board.post(p);
  });
  std::vector<double> lat;
  {
    remote::Participant monitor(domain);
    const dds_entity_t status = monitor.reader<wb::FsmStatus>(true);  // the robot starts on this match
    (void)status;
    const dds_entity_t reader = monitor.reader<wb::Pose>(true);
    int wstatus = 0;
    receive<wb::Pose>(reader, std::chrono::milliseconds{static_cast<long>(o.seconds * 1000) + 30000},
                      [&](const auto& s) { lat.push_back(now_us(epoch) - s.x); },
                      [&] { return ::waitpid(child, &wstatus, WNOHANG) == child; });
    if (!WIFEXITED(wstatus) || WEXITSTATUS(wstatus) != 0) return std::nullopt;
  }
  Latency l;
  l.samples = lat.size();
  l.posted = static_cast<std::size_t>(o.seconds * hz);
  if (lat.empty()) return std::nullopt;
  l.p50_us = quantile(lat, 0.5);
  l.p99_us = quantile(lat, 0.99);
  l.max_us = *std::max_element(lat.begin(), lat.end());
  double sum = 0;
  for (double v : lat) sum += v;
  l.mean_us = sum / static_cast<double>(lat.size());
  return l;
}

struct Rate {
  double hz = 0;
  std::uint64_t posted = 0;
  std::uint64_t received = 0;  // distinct generations
};

std::optional<Rate> measure_rate(const Options& o, double hz) {
  const auto domain = bench_domain("rate" + std::to_string(static_cast<long>(hz)));
  const pid_t child = robot_process(domain, o, hz, [](wb::Whiteboard& board, std::uint64_t i) {
    wb::FsmStatus s;
    s.machine = "Bench";
    s.state = "Run";
    s.ringlets = i;
    board.post(s);
  });
  Rate r{hz, static_cast<std::uint64_t>(o.seconds * hz), 0};
  std::vector<bool> seen(r.posted + 2, false);
  remote::Participant monitor(domain);
  const dds_entity_t reader = monitor.reader<wb::FsmStatus>(true);
  int wstatus = 0;
  bool exited = false;
  auto last_sample = Clock::now();
  receive<wb::FsmStatus>(reader, std::chrono::milliseconds{static_cast<long>(o.seconds * 1000) + 30000},
                         [&](const auto& s) {
                           last_sample = Clock::now();
                           if (s.generation < seen.size() && !seen[s.generation]) {
                             seen[s.generation] = true;
                             ++r.received;
                           }
                         },
                         [&] {
                           // The robot flushed before it exited: once it is gone and nothing has
                           // come for half a second, what is missing is lost.
                           if (!exited) exited = ::waitpid(child, &wstatus, WNOHANG) == child;
                           return exited && (r.received >= r.posted || Clock::now() - last_sample > 500ms);
                         });
  if (!exited) exited = ::waitpid(child, &wstatus, 0) == child;
  if (!WIFEXITED(wstatus) || WEXITSTATUS(wstatus) != 0) return std::nullopt;
  return r;
}

struct Ddsperf {
  double p50_us = 0, p99_us = 0;  // one way: the round trip halved
  std::size_t roundtrips = 0;
};

std::optional<Ddsperf> measure_ddsperf(const Options& o) {
  const std::string uri = "CYCLONEDDS_URI=" + remote::loopback_config();
  std::vector<std::string> env_strings;
  for (char** e = environ; *e != nullptr; ++e) {
    if (std::string(*e).rfind("CYCLONEDDS_URI=", 0) != 0) env_strings.emplace_back(*e);
  }
  env_strings.push_back(uri);
  std::vector<char*> env;
  for (auto& s : env_strings) env.push_back(s.data());
  env.push_back(nullptr);
  const std::string dur = std::to_string(static_cast<int>(o.seconds) + 2);
  const std::string ping_dur = std::to_string(static_cast<int>(o.seconds) + 1);
  char pong_log[] = "/tmp/ringlet-ddsperf-pong-XXXXXX";
  char ping_log[] = "/tmp/ringlet-ddsperf-ping-XXXXXX";
  const int pong_fd = ::mkstemp(pong_log);
  const int ping_fd = ::mkstemp(ping_log);
  if (pong_fd < 0 || ping_fd < 0) return std::nullopt;
  const auto spawn = [&](std::vector<std::string> args, int fd) -> pid_t {
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_adddup2(&fa, fd, 1);
    posix_spawn_file_actions_adddup2(&fa, fd, 2);
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    pid_t pid = -1;
    if (posix_spawnp(&pid, "ddsperf", &fa, nullptr, argv.data(), env.data()) != 0) pid = -1;
    posix_spawn_file_actions_destroy(&fa);
    return pid;
  };
  const pid_t pong = spawn({"ddsperf", "-D", dur, "pong"}, pong_fd);
  const pid_t ping = spawn({"ddsperf", "-D", ping_dur, "ping", "1000Hz"}, ping_fd);
  int st = 0;
  if (ping > 0) ::waitpid(ping, &st, 0);
  if (pong > 0) ::waitpid(pong, &st, 0);
  ::close(pong_fd);
  ::close(ping_fd);
  std::ifstream in(ping_log);
  std::string line;
  // "... mean 28.929us min 18.664us 50% 27.907us 90% 32.661us 99% 40.475us max 483.507us cnt 885"
  const std::regex re(R"(50% ([0-9.]+)us .*99% ([0-9.]+)us .*cnt ([0-9]+))");
  std::vector<double> p50, p99;
  std::size_t count = 0;
  while (std::getline(in, line)) {
    std::smatch m;
    if (std::regex_search(line, m, re)) {
      p50.push_back(std::stod(m[1]) / 2.0);
      p99.push_back(std::stod(m[2]) / 2.0);
      count += std::stoul(m[3]);
    }
  }
  std::remove(pong_log);
  std::remove(ping_log);
  if (p50.empty()) return std::nullopt;
  // Each line is one second's statistics: the median of those seconds.
  return Ddsperf{quantile(p50, 0.5), quantile(p99, 0.5), count};
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"ringlet-remote-bench: post -> monitor latency and the sustained lossless rate of the whiteboard "
               "over the bridge on loopback, beside ddsperf's latency. Exit codes: 0 measured, 1 a measurement "
               "failed, 2 bad flags."};
  Options o;
  app.add_option("--seconds", o.seconds, "seconds per measurement")->check(CLI::Range(0.2, 600.0))->capture_default_str();
  app.add_option("--rates", o.rates, "FsmStatus rates to try (Hz)")->check(CLI::Range(1.0, 1e6))->delimiter(',')->capture_default_str();
  app.add_option("--poll-us", o.poll_us, "the bridge thread's period (µs; the firmware's default is 2000)")
      ->check(CLI::Range(50, 1000000))->capture_default_str();
  app.add_option("--depth", o.depth, "whiteboard ring depth (the firmware's is 8)")->check(CLI::Range(2, 4096))->capture_default_str();
  app.add_flag("!--no-ddsperf", o.ddsperf, "skip the ddsperf comparison");
  app.add_option("--json", o.json, "write the figures as JSON");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  nlohmann::json out{{"seconds", o.seconds}, {"poll_us", o.poll_us}, {"depth", o.depth}};
  int rc = 0;
  std::printf("bridge: poll every %d us, whiteboard depth %zu, loopback\n", o.poll_us, o.depth);
  const auto lat = measure_latency(o);
  if (lat) {
    std::printf("latency  post -> monitor (Pose, 1 kHz, %zu of %zu received): p50 %.1f us  p99 %.1f us  mean %.1f us  max %.1f us\n",
                lat->samples, lat->posted, lat->p50_us, lat->p99_us, lat->mean_us, lat->max_us);
    out["latency"] = {{"p50_us", lat->p50_us}, {"p99_us", lat->p99_us}, {"mean_us", lat->mean_us},
                      {"max_us", lat->max_us}, {"received", lat->samples}, {"posted", lat->posted}};
  } else {
    std::fprintf(stderr, "ringlet-remote-bench: the latency measurement failed\n");
    rc = 1;
  }
  if (o.ddsperf) {
    const auto d = measure_ddsperf(o);
    if (d) {
      std::printf("ddsperf  ping/pong one way (round trip / 2, %zu round trips): p50 %.1f us  p99 %.1f us\n", d->roundtrips,
                  d->p50_us, d->p99_us);
      out["ddsperf"] = {{"p50_us", d->p50_us}, {"p99_us", d->p99_us}, {"roundtrips", d->roundtrips}};
      if (lat) {
        std::printf("ratio    bridge / ddsperf: p50 %.1fx  p99 %.1fx\n", lat->p50_us / d->p50_us, lat->p99_us / d->p99_us);
        out["ratio_p50"] = lat->p50_us / d->p50_us;
        out["ratio_p99"] = lat->p99_us / d->p99_us;
      }
    } else {
      std::fprintf(stderr, "ringlet-remote-bench: ddsperf gave no latency (is cyclonedds-tools installed?)\n");
      rc = 1;
    }
  }
  double sustained = 0;
  nlohmann::json rates = nlohmann::json::array();
  for (const double hz : o.rates) {
    const auto r = measure_rate(o, hz);
    if (!r) {
      std::fprintf(stderr, "ringlet-remote-bench: the rate measurement at %.0f Hz failed\n", hz);
      rc = 1;
      continue;
    }
    const std::uint64_t lost = r->posted - std::min(r->posted, r->received);
    std::printf("rate     %7.0f Hz FsmStatus for %.1f s: %llu posted, %llu received, %llu lost\n", hz, o.seconds,
                static_cast<unsigned long long>(r->posted), static_cast<unsigned long long>(r->received),
                static_cast<unsigned long long>(lost));
    rates.push_back({{"hz", hz}, {"posted", r->posted}, {"received", r->received}, {"lost", lost}});
    if (lost == 0) sustained = std::max(sustained, hz);
  }
  std::printf("sustained lossless rate: %.0f Hz of the rates tried\n", sustained);
  out["rates"] = rates;
  out["sustained_hz"] = sustained;
  if (!o.json.empty()) {
    std::ofstream f(o.json);
    f << out.dump(2) << '\n';
    if (!f) {
      std::fprintf(stderr, "ringlet-remote-bench: cannot write %s\n", o.json.c_str());
      return 1;
    }
  }
  return rc;
}
