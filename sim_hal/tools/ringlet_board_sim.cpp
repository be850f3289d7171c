// ringlet-board-sim: the simulated robot behind the board's CAN protocol on a SocketCAN interface
// (hal/can/README.md), so that the firmware, unchanged ([robot] backend = "can"), drives a
// simulated car over a real bus: hardware-in-the-loop without the hardware.
//
//   ip link add dev vcan0 type vcan && ip link set up vcan0
//   ringlet-board-sim --interface vcan0 --world sim_hal/worlds/courtyard.world &
//   ringlet --config <courtyard with backend = "can", [can] interface = "vcan0"> --realtime
//
// It steps the world every --period-us on the real clock (absolute deadlines), and, like a real
// board, stops the car when no CTRL_DRIVE has come for --command-timeout-ms. Progress every 5 s;
// a summary at the end. Exit codes: 0 ran (Ctrl-C or --duration), 2 bad input (flags, world
// file, an interface that cannot be opened).
#include <CLI/CLI.hpp>

#include <atomic>
#include <csignal>
#include <cstdio>
#include <iostream>

#include "ringlet/hal/monotonic_clock.hpp"
#include "ringlet/sim_hal/software_board.hpp"
#include "ringlet/sim_hal/world.hpp"

namespace {

std::atomic<bool> g_stop{false};
extern "C" void on_signal(int) { g_stop.store(true); }

}  // namespace

int main(int argc, char** argv) {
  using namespace ringlet;
  CLI::App app{"ringlet-board-sim: the simulated robot as a CAN board on a SocketCAN interface (hal/can/README.md). "
               "Exit codes: 0 ran, 2 bad input or the interface cannot be opened."};
  std::string interface = "vcan0";
  std::string world_file = "sim_hal/worlds/courtyard.world";
  std::uint64_t seed = 42;
  int period_us = 10000;
  int timeout_ms = 100;
  double duration_s = 0.0;
  int laser_beams = 181;
  app.add_option("-i,--interface", interface, "SocketCAN interface")->capture_default_str();
  app.add_option("-w,--world", world_file, "world file (sim_hal/worlds/*.world)")->capture_default_str();
  app.add_option("--seed", seed, "the simulator's seed")->capture_default_str();
  app.add_option("--period-us", period_us, "one world step (the firmware's executive period)")->check(CLI::Range(1000, 100000))->capture_default_str();
  app.add_option("--command-timeout-ms", timeout_ms, "the board's watchdog: stop the car after this long without CTRL_DRIVE")
      ->check(CLI::Range(10, 10000))->capture_default_str();
  app.add_option("--laser-beams", laser_beams, "beams per laser scan")->check(CLI::Range(1, 721))->capture_default_str();
  app.add_option("-d,--duration", duration_s, "seconds to run (0: until Ctrl-C)")->check(CLI::Range(0.0, 86400.0))->capture_default_str();
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }

  sim_hal::SimConfig sim;
  sim.period = hal::Nanos{static_cast<std::int64_t>(period_us) * 1000};
  sim.seed = seed;
  sim.laser_beams = laser_beams;
  std::unique_ptr<sim_hal::SimRobot> car;
  try {
    car = std::make_unique<sim_hal::SimRobot>(sim_hal::load_world(world_file), sim);
  } catch (const std::exception& e) {
    std::cerr << "ringlet-board-sim: " << e.what() << "\n";
    return 2;
  }
  std::string error;
  hal::can::CanSocket socket = hal::can::CanSocket::open(interface, &error);
  if (!socket.is_open()) {
    std::cerr << "ringlet-board-sim: " << error << "\n";
    return 2;
  }
  sim_hal::SoftwareBoardSettings settings;
  settings.command_timeout = hal::Nanos{static_cast<std::int64_t>(timeout_ms) * 1'000'000};
  sim_hal::SoftwareBoard board(*car, std::move(socket), settings);
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);

  hal::MonotonicClock clock;
  const hal::Nanos start = clock.now();
  hal::Nanos next = start;
  hal::Nanos next_progress = start + std::chrono::seconds{5};
  std::cout << "ringlet-board-sim: " << world_file << " on " << interface << ", a step every " << period_us
            << " us, watchdog " << timeout_ms << " ms (Ctrl-C ends)" << std::endl;
  while (!g_stop.load() && (duration_s <= 0.0 || next - start < std::chrono::duration<double>(duration_s))) {
    clock.sleep_until(next);
    board.step(clock.now());
    next += sim.period;
    if (clock.now() >= next_progress) {
      const auto& c = board.counts();
      std::printf("board: %.0f s, %llu commands, %.2f m driven, state %d, %llu watchdog stops\n",
                  std::chrono::duration<double>(clock.now() - start).count(), static_cast<unsigned long long>(c.commands),
                  car->distance_travelled(), static_cast<int>(board.state()), static_cast<unsigned long long>(c.watchdog_stops));
      std::fflush(stdout);
      next_progress += std::chrono::seconds{5};
    }
  }
  const auto& c = board.counts();
  std::printf("board done: %llu steps, %llu commands, %llu refused, %llu watchdog stops, %llu frames sent, %llu dropped (queue full), %.2f m driven, %llu collisions\n",
              static_cast<unsigned long long>(c.steps), static_cast<unsigned long long>(c.commands),
              static_cast<unsigned long long>(c.refused), static_cast<unsigned long long>(c.watchdog_stops),
              static_cast<unsigned long long>(c.frames_sent), static_cast<unsigned long long>(c.tx_full),
              car->distance_travelled(), static_cast<unsigned long long>(car->collisions()));
  return 0;
}
