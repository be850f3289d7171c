// ringlet-monitor: watches robots' whiteboards over DDS (the firmware's [remote] bridge).
//
//   ringlet-monitor list                 robots, types and rates seen during --wait seconds
//   ringlet-monitor echo TYPE            samples of one type as the whiteboard's text, or --json lines
//   ringlet-monitor fsm                  every machine's state, previous state and ringlets per robot
//   ringlet-monitor --robot N control MACHINE suspend|resume|restart
//                                        asks robot N (its [remote] accept lists FsmControl) and
//                                        waits until its FsmStatus shows the effect
//   ringlet-monitor serve [--port 8080]  the live page in a browser (field, machines, timing)
//   ringlet-monitor record FILE          every sample heard, as JSON lines (remote/README.md)
//   ringlet-monitor replay FILE          publishes a recording again, as the robots did
//   ringlet-monitor --plotjuggler HOST:PORT   every sample as JSON over UDP to PlotJuggler
//
// Exit codes: 0 done · 1 nothing heard (no robot found: the message names the domain, partition
// and network) · 2 bad input (flags, type name, configuration file) or DDS refused to start.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <map>
#include <string>
#include <thread>
#include <tuple>

#include "monitor_common.hpp"

namespace ringlet::monitor {

std::atomic<bool> g_stop{false};

std::string network_text(const Options& o) {
  return "DDS domain " + std::to_string(o.domain) + ", partition \"" + o.partition + "\", " +
         (o.config.empty() ? std::string("loopback only (interface lo, peer 127.0.0.1)")
                           : "the network of " + o.config);
}

remote::DomainConfig domain_of(const Options& o) {
  remote::DomainConfig d{static_cast<std::uint32_t>(o.domain), o.partition, ""};
  if (!o.config.empty()) {
    const hal::FileRead f = hal::read_file(o.config, "Cyclone DDS configuration");
    if (!f.ok()) throw remote::RemoteError(f.error);
    d.cyclone_config = f.bytes;
  }
  return d;
}

}  // namespace ringlet::monitor

namespace {

using namespace ringlet;
using namespace ringlet::monitor;

extern "C" void on_signal(int) { g_stop.store(true); }

// ---- commands ----------------------------------------------------------------------------------
int list(const Options& o) {
  Tap tap(o);
  struct Seen {
    std::uint64_t samples = 0;
    std::uint64_t first = 0, last = 0;  // generations
  };
  std::map<std::pair<int, std::string_view>, Seen> seen;
  const auto start = Clock::now();
  while (!g_stop.load() && Clock::now() - start < std::chrono::duration<double>(o.wait_s)) {
    tap.poll([&]<class T>(std::uint16_t robot, std::uint64_t gen, const T&) {
      Seen& s = seen[{robot, T::kName}];
      if (s.samples == 0) s.first = gen;
      ++s.samples;
      s.last = gen;
    });
    std::this_thread::sleep_for(std::chrono::milliseconds{5});
  }
  const double secs = std::chrono::duration<double>(Clock::now() - start).count();
  if (seen.empty()) {
    std::cerr << "ringlet-monitor: no robot found in " << o.wait_s << " s on " << network_text(o) << "\n";
    return 1;
  }
  std::printf("%-6s %-18s %-7s %10s %12s %10s\n", "ROBOT", "TYPE", "QOS", "SAMPLES", "GENERATION", "RATE Hz");
  for (const auto& [key, s] : seen) {
    const auto info = wb::find_type(key.second);
    std::printf("%-6d %-18.*s %-7s %10llu %12llu %10.1f\n", key.first, static_cast<int>(key.second.size()),
                key.second.data(), remote::to_string(remote::topic_qos(info->id).kind),
                static_cast<unsigned long long>(s.samples), static_cast<unsigned long long>(s.last),
                static_cast<double>(s.samples) / secs);
  }
  if (tap.invalid() > 0) std::printf("(%llu samples refused: values without whiteboard meaning)\n", static_cast<unsigned long long>(tap.invalid()));
  return 0;
}

template <wb::Message T>
int echo(const Options& o) {
  remote::Participant p(domain_of(o));
  const dds_entity_t reader = p.reader<T>(true);
  long printed = 0;
  std::uint64_t invalid = 0;
  const auto start = Clock::now();
  const bool timed = o.wait_s > 0.0 && o.count == 0 ? false : o.wait_s > 0.0;
  while (!g_stop.load() && (o.count == 0 || printed < o.count)) {
    take_all<T>(reader, invalid, [&](std::uint16_t robot, std::uint64_t gen, const T& m) {
      if ((o.robot && *o.robot != robot) || (o.count > 0 && printed >= o.count)) return;
      if (o.json) {
        std::cout << message_json(m, robot, gen).dump() << '\n';
      } else {
        std::cout << "robot " << robot << " " << T::kName << " #" << gen << ": " << m.description() << '\n';
      }
      ++printed;
    });
    std::cout.flush();
    if (timed && Clock::now() - start > std::chrono::duration<double>(o.wait_s)) break;
    std::this_thread::sleep_for(std::chrono::milliseconds{2});
  }
  if (printed == 0) {
    std::cerr << "ringlet-monitor: no " << T::kName << " received on " << network_text(o) << "\n";
    return 1;
  }
  return 0;
}

int fsm(const Options& o) {
  remote::Participant p(domain_of(o));
  const dds_entity_t reader = p.reader<wb::FsmStatus>();  // transient-local: current states at once
  std::map<std::pair<int, std::string>, std::pair<wb::FsmStatus, std::uint64_t>> table;
  std::uint64_t invalid = 0;
  const auto start = Clock::now();
  auto next_draw = start;
  const auto draw = [&](bool clear) {
    if (clear) std::cout << "\x1b[H\x1b[2J";
    char line[256];
    std::snprintf(line, sizeof line, "%-6s %-14s %-16s %-16s %12s %-9s %s\n", "ROBOT", "MACHINE", "STATE", "PREVIOUS",
                  "RINGLETS", "SUSPENDED", "GENERATION");
    std::cout << line;
    for (const auto& [key, v] : table) {
      const wb::FsmStatus& s = v.first;
      std::snprintf(line, sizeof line, "%-6d %-14s %-16.*s %-16.*s %12llu %-9s %llu\n", key.first, key.second.c_str(),
                    static_cast<int>(s.state.view().size()), s.state.view().data(),
                    static_cast<int>(s.previous.view().size()), s.previous.view().data(),
                    static_cast<unsigned long long>(s.ringlets), s.suspended ? "yes" : "no",
                    static_cast<unsigned long long>(v.second));
      std::cout << line;
    }
    std::cout.flush();
  };
  auto last_update = start;
  while (!g_stop.load()) {
    take_all<wb::FsmStatus>(reader, invalid, [&](std::uint16_t robot, std::uint64_t gen, const wb::FsmStatus& s) {
      if (o.robot && *o.robot != robot) return;
      auto& slot = table[{robot, std::string(s.machine.view())}];
      if (gen >= slot.second) slot = {s, gen};
      last_update = Clock::now();
    });
    const auto now = Clock::now();
    if (o.once) {
      // Done once the states have settled (nothing new for half a second), or at --wait.
      if (!table.empty() && now - last_update > std::chrono::milliseconds{500}) break;
      if (now - start > std::chrono::duration<double>(o.wait_s)) break;
    } else if (now >= next_draw) {
      draw(true);
      next_draw = now + std::chrono::milliseconds{200};
    }
    std::this_thread::sleep_for(std::chrono::milliseconds{5});
  }
  if (table.empty()) {
    std::cerr << "ringlet-monitor: no machine states received on " << network_text(o) << "\n";
    return 1;
  }
  if (o.once) draw(false);
  return 0;
}

std::string past(const std::string& verb) { return verb + (verb.ends_with('e') ? "d" : "ed"); }

// Asks robot --robot to suspend, resume or restart a machine, and waits until its FsmStatus shows
// the effect.
int control(const Options& o, const std::string& machine, const std::string& command_text) {
  if (!o.robot) {
    std::cerr << "ringlet-monitor: control: --robot is required (which robot to ask)\n";
    return 2;
  }
  wb::FsmControl request;
  bool known = false;
  for (const auto& e : wb::EnumTraits<wb::FsmCommand>::kEntries) {
    if (e.text == command_text) {
      request.command = e.value;
      known = true;
    }
  }
  if (!known) {
    std::cerr << "ringlet-monitor: control: command \"" << command_text << "\" must be suspend, resume or restart\n";
    return 2;
  }
  if (machine.empty() || !request.machine.assign(machine)) {
    std::cerr << "ringlet-monitor: control: machine name \"" << machine << "\" must be 1 to "
              << decltype(request.machine)::kCapacity << " characters\n";
    return 2;
  }
  const auto robot = static_cast<std::uint16_t>(*o.robot);
  remote::Participant p(domain_of(o));
  const dds_entity_t status_reader = p.reader<wb::FsmStatus>();
  const dds_entity_t writer = p.request_writer<wb::FsmControl>();
  const auto deadline = Clock::now() + std::chrono::duration<double>(o.wait_s);
  dds_publication_matched_status_t matched{};
  while (!g_stop.load() && Clock::now() < deadline &&
         (dds_get_publication_matched_status(writer, &matched) < 0 || matched.current_count == 0)) {
    std::this_thread::sleep_for(std::chrono::milliseconds{5});
  }
  if (matched.current_count == 0) {
    std::cerr << "ringlet-monitor: control: no robot takes remote writes on " << network_text(o)
              << " (is robot " << robot << " running with [remote] accept = [\"FsmControl\"]?)\n";
    return 1;
  }
  // What the machine looked like before: a restart shows as a newer status of that machine.
  std::uint64_t invalid = 0;
  std::uint64_t newest_before = 0;
  take_all<wb::FsmStatus>(status_reader, invalid, [&](std::uint16_t r, std::uint64_t gen, const wb::FsmStatus& s) {
    if (r == robot && s.machine.view() == machine) newest_before = std::max(newest_before, gen);
  });
  remote::DdsType<wb::FsmControl>::Sample sample{};
  remote::to_sample(request, robot, 1, sample);
  remote::check(dds_write(writer, &sample), "sending the request");
  (void)dds_wait_for_acks(writer, DDS_SECS(5));
  while (!g_stop.load() && Clock::now() < deadline) {
    bool done = false;
    take_all<wb::FsmStatus>(status_reader, invalid, [&](std::uint16_t r, std::uint64_t gen, const wb::FsmStatus& s) {
      if (done || r != robot || s.machine.view() != machine || gen <= newest_before) return;
      const bool effect = request.command == wb::kSuspend  ? s.suspended
                          : request.command == wb::kResume ? !s.suspended
                                                           : true;
      if (!effect) return;
      std::cout << "robot " << robot << ": " << machine << " " << past(command_text) << ": state " << s.state.view()
                << (s.suspended ? " (suspended)" : "") << ", ringlets " << s.ringlets << "\n";
      done = true;
    });
    if (done) return 0;
    std::this_thread::sleep_for(std::chrono::milliseconds{5});
  }
  std::cerr << "ringlet-monitor: control: robot " << robot << " did not show " << machine << " " << past(command_text)
            << " within " << o.wait_s << " s (it may have refused the request: its log says why)\n";
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "ringlet-monitor: watch robots' whiteboards over DDS (the firmware's [remote] bridge). "
      "Exit codes: 0 done, 1 nothing heard, 2 bad input or DDS refused to start."};
  Options o;
  app.add_option("--domain", o.domain, "DDS domain id")->check(CLI::Range(0, 232))->capture_default_str();
  app.add_option("--partition", o.partition, "DDS partition (the robots' [remote] partition)")->capture_default_str();
  app.add_option("--config", o.config, "Cyclone DDS XML file for a real network (default: loopback only)")
      ->check(CLI::ExistingFile);
  app.add_option("--robot", o.robot, "only this robot id")->check(CLI::Range(0, 65535));
  std::string plotjuggler_target;
  app.add_option("--plotjuggler", plotjuggler_target,
                 "stream every sample as JSON over UDP to PlotJuggler's UDP server (HOST:PORT), until Ctrl-C or --wait");
  double stream_wait = 0.0;
  app.add_option("--wait", stream_wait, "with --plotjuggler alone: stop after this many seconds")->check(CLI::Range(0.1, 86400.0));
  app.require_subcommand(0, 1);

  auto* list_cmd = app.add_subcommand("list", "robots, types and rates heard during --wait seconds");
  list_cmd->add_option("--wait", o.wait_s, "seconds to listen")->check(CLI::Range(0.1, 3600.0))->capture_default_str();

  auto* echo_cmd = app.add_subcommand("echo", "samples of one type, as the whiteboard's text or JSON lines");
  echo_cmd->add_option("type", o.type, "whiteboard type, e.g. FsmStatus")->required();
  echo_cmd->add_flag("--json", o.json, "one JSON object per line (type, robot, generation, fields)");
  echo_cmd->add_option("-n,--count", o.count, "stop after this many samples (0: until Ctrl-C)")->check(CLI::Range(0L, 1000000000L));
  echo_cmd->add_option("--wait", o.wait_s, "with --count: give up after this many seconds")->check(CLI::Range(0.1, 86400.0));

  auto* fsm_cmd = app.add_subcommand("fsm", "a live table of every machine's state per robot (Ctrl-C ends)");
  fsm_cmd->add_flag("--once", o.once, "print the table once the states have settled (nothing new for 0.5 s), or after --wait seconds, and exit");
  fsm_cmd->add_option("--wait", o.wait_s, "with --once: most seconds to listen")->check(CLI::Range(0.1, 3600.0));

  auto* control_cmd = app.add_subcommand("control", "ask --robot to suspend, resume or restart a machine ([remote] accept must list FsmControl)");
  std::string control_machine;
  std::string control_command;
  control_cmd->add_option("machine", control_machine, "machine name, e.g. Mission")->required();
  control_cmd->add_option("command", control_command, "suspend, resume or restart")->required();
  control_cmd->add_option("--wait", o.wait_s, "seconds to wait for the robot and the effect")->check(CLI::Range(0.1, 3600.0));

  auto* serve_cmd = app.add_subcommand("serve", "the live page: field, pose, plan, machines and timing of every robot, in a browser");
  ServeOptions serve_options;
  serve_cmd->add_option("--port", serve_options.port, "TCP port (0: any free one, printed)")->check(CLI::Range(0, 65535))->capture_default_str();
  serve_cmd->add_option("--bind", serve_options.bind, "address to listen on (0.0.0.0: every interface)")->capture_default_str();

  auto* record_cmd = app.add_subcommand("record", "write every sample heard to FILE as JSON lines (Ctrl-C, --wait or --count ends)");
  std::string record_file;
  record_cmd->add_option("file", record_file, "where to write (replaced)")->required();
  record_cmd->add_option("--wait", o.wait_s, "stop after this many seconds")->check(CLI::Range(0.1, 86400.0));
  record_cmd->add_option("-n,--count", o.count, "stop after this many samples")->check(CLI::Range(0L, 1000000000L));

  auto* replay_cmd = app.add_subcommand("replay", "publish a recording again, as the robots did (for serve, fsm, echo or other DDS tools)");
  std::string replay_file;
  double replay_speed = 1.0;
  replay_cmd->add_option("file", replay_file, "a file written by record")->required()->check(CLI::ExistingFile);
  replay_cmd->add_option("--wait", o.wait_s, "most seconds to wait for a monitor (a reader of FsmStatus) before publishing")->check(CLI::Range(0.0, 3600.0));
  replay_cmd->add_option("--speed", replay_speed, "times the recorded pace (0: as fast as possible)")->check(CLI::Range(0.0, 1000.0))->capture_default_str();

  try {
    app.parse(argc, argv);
    if (app.get_subcommands().empty() && plotjuggler_target.empty()) {
      throw CLI::RequiredError("A command (list, echo, fsm, control, serve, record, replay) or --plotjuggler");
    }
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  try {
    if (!plotjuggler_target.empty() && app.get_subcommands().empty()) {
      if (stream_wait > 0.0) o.wait_s = stream_wait;
      return plotjuggler(o, plotjuggler_target, stream_wait > 0.0);
    }
    if (!plotjuggler_target.empty()) {
      std::cerr << "ringlet-monitor: --plotjuggler streams on its own; run it beside " << app.get_subcommands()[0]->get_name()
                << " as a second ringlet-monitor\n";
      return 2;
    }
    if (serve_cmd->parsed()) return serve(o, serve_options);
    if (record_cmd->parsed()) return record(o, record_file, record_cmd->count("--wait") > 0);
    if (replay_cmd->parsed()) return replay(o, replay_file, replay_speed);
    if (list_cmd->parsed()) return list(o);
    if (fsm_cmd->parsed()) return fsm(o);
    if (control_cmd->parsed()) return control(o, control_machine, control_command);
    int rc = -1;
    wb::for_each_type([&]<class T>(std::type_identity<T>) {
      if (T::kName == o.type) rc = echo<T>(o);
    });
    if (rc < 0) {
      std::string names;
      for (const auto& t : wb::kTypes) names += (names.empty() ? "" : ", ") + std::string(t.name);
      std::cerr << "ringlet-monitor: echo: no whiteboard type \"" << o.type << "\"; the types are " << names << "\n";
      return 2;
    }
    return rc;
  } catch (const remote::RemoteError& e) {
    std::cerr << "ringlet-monitor: " << e.what() << "\n";
    return 2;
  }
}
