// ringlet-monitor --plotjuggler HOST:PORT: every sample heard, as one JSON object per UDP datagram,
// the way PlotJuggler's "UDP Server" (message protocol JSON) reads them:
//   {"timestamp": <s since the epoch, when heard>, "robot6": {"Pose": {"x": 1.2, ...}}}
// PlotJuggler flattens that into series such as /robot6/Pose/x (arrays: /robot6/LaserScan/range_mm/17);
// FsmStatus goes one level deeper, by machine (/robot6/FsmStatus/Safety/ringlets), so machines do
// not overwrite each other. Enums are numbers and text is left out: PlotJuggler plots numbers.
// Tick "use field as timestamp if available" there to plot on the time the monitor heard them.
#include <netdb.h>
#include <sys/socket.h>
#include <unistd.h>

#include <iostream>
#include <thread>

#include "monitor_common.hpp"

namespace ringlet::monitor {
namespace {

// Without the strings: PlotJuggler plots numbers.
void drop_text(nlohmann::json& fields) {
  for (auto it = fields.begin(); it != fields.end();) {
    it = it->is_string() ? fields.erase(it) : std::next(it);
  }
}

class UdpTarget {
 public:
  // "" and a connected socket, or why not.
  std::string open(const std::string& target) {
    const auto colon = target.rfind(':');
    if (colon == std::string::npos || colon == 0 || colon + 1 == target.size()) {
      return "--plotjuggler \"" + target + "\": expected HOST:PORT, e.g. 127.0.0.1:9870";
    }
    const std::string host = target.substr(0, colon), port = target.substr(colon + 1);
    addrinfo hints{};
    hints.ai_socktype = SOCK_DGRAM;
    addrinfo* found = nullptr;
    if (const int rc = getaddrinfo(host.c_str(), port.c_str(), &hints, &found); rc != 0) {
      return "--plotjuggler \"" + target + "\": " + gai_strerror(rc);
    }
    std::string error;
    fd_ = ::socket(found->ai_family, found->ai_socktype, found->ai_protocol);
    if (fd_ < 0 || ::connect(fd_, found->ai_addr, found->ai_addrlen) != 0) {
      error = "--plotjuggler \"" + target + "\": cannot open a UDP socket to it";
    }
    freeaddrinfo(found);
    return error;
  }
  ~UdpTarget() {
    if (fd_ >= 0) ::close(fd_);
  }
  // A datagram nobody receives (PlotJuggler not started yet) is not an error: it is counted.
  bool send(const std::string& datagram) const noexcept {
    return ::send(fd_, datagram.data(), datagram.size(), 0) == static_cast<ssize_t>(datagram.size());
  }

 private:
  int fd_ = -1;
};

}  // namespace

int plotjuggler(const Options& o, const std::string& target, bool wait_given) {
  UdpTarget udp;
  if (const std::string error = udp.open(target); !error.empty()) {
    std::cerr << "ringlet-monitor: " << error << "\n";
    return 2;
  }
  Tap tap(o);
  const auto start = Clock::now();
  std::uint64_t sent = 0, unsent = 0;
  auto next_progress = start + std::chrono::seconds{5};
  std::cerr << "streaming to PlotJuggler's UDP server at " << target << " (JSON; Ctrl-C ends)\n";
  while (!g_stop.load() && (!wait_given || Clock::now() - start < std::chrono::duration<double>(o.wait_s))) {
    tap.poll([&]<class T>(std::uint16_t robot, std::uint64_t, const T& m) {
      nlohmann::json fields = fields_json(m, /*numeric_enums=*/true);
      drop_text(fields);
      nlohmann::json body = fields;
      if constexpr (std::is_same_v<T, wb::FsmStatus>) body = {{std::string(m.machine.view()), fields}};
      const double now = std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
      const nlohmann::json datagram = {{"timestamp", now}, {"robot" + std::to_string(robot), {{std::string(T::kName), body}}}};
      (udp.send(datagram.dump()) ? sent : unsent) += 1;
    });
    if (Clock::now() >= next_progress) {
      std::cerr << "plotjuggler: " << sent << " datagrams sent" << (unsent > 0 ? ", " + std::to_string(unsent) + " refused by the network" : "") << "\n";
      next_progress += std::chrono::seconds{5};
    }
    std::this_thread::sleep_for(std::chrono::milliseconds{5});
  }
  if (sent == 0) {
    std::cerr << "ringlet-monitor: --plotjuggler: nothing heard on " << network_text(o) << "\n";
    return 1;
  }
  std::cout << "sent " << sent << " datagrams to " << target << "\n";
  return 0;
}

}  // namespace ringlet::monitor
