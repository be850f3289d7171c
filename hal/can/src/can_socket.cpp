#include "ringlet/hal/can/can_socket.hpp"

#include <fcntl.h>
#include <linux/can.h>
#include <linux/can/error.h>
#include <linux/can/raw.h>
#include <net/if.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <utility>

namespace ringlet::hal::can {
namespace {

bool set_nonblocking(int fd) noexcept {
  const int flags = ::fcntl(fd, F_GETFL, 0);
  return flags >= 0 && ::fcntl(fd, F_SETFL, flags | O_NONBLOCK) == 0;
}

}  // namespace

CanSocket CanSocket::open(std::string_view interface, std::string* error) {
  // Messages are built only for a caller that asked: a reconnect on the cycle path allocates nothing.
  const auto fail = [&](const char* what, bool with_errno, const char* hint) {
    if (error != nullptr) {
      *error = "CAN interface \"" + std::string(interface) + "\": " + what;
      if (with_errno) *error += std::string(": ") + std::strerror(errno);
      *error += hint;
    }
    return CanSocket{};
  };
  if (interface.empty() || interface.size() >= IFNAMSIZ) return fail("a name of 1 to 15 characters", false, "");
  const int fd = ::socket(PF_CAN, SOCK_RAW | SOCK_NONBLOCK | SOCK_CLOEXEC, CAN_RAW);
  if (fd < 0) {
    if (error != nullptr) *error = std::string("CAN socket: ") + std::strerror(errno) + " (is the kernel's can-raw module loaded?)";
    return {};
  }
  CanSocket s(fd);
  ifreq ifr{};
  std::memcpy(ifr.ifr_name, interface.data(), interface.size());  // zero-terminated by ifr{}
  if (::ioctl(fd, SIOCGIFINDEX, &ifr) < 0) return fail("no such interface", true, " (ip link show type can / vcan)");
  const can_err_mask_t errors = CAN_ERR_BUSOFF | CAN_ERR_CRTL | CAN_ERR_RESTARTED | CAN_ERR_TX_TIMEOUT;
  if (::setsockopt(fd, SOL_CAN_RAW, CAN_RAW_ERR_FILTER, &errors, sizeof errors) < 0) {
    return fail("cannot receive error frames", true, "");
  }
  sockaddr_can addr{};
  addr.can_family = AF_CAN;
  addr.can_ifindex = ifr.ifr_ifindex;
  if (::bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) < 0) return fail("bind", true, "");
  return s;
}

CanSocket CanSocket::adopt(int fd) noexcept {
  (void)set_nonblocking(fd);
  return CanSocket(fd);
}

CanSocket::~CanSocket() { close(); }
CanSocket::CanSocket(CanSocket&& o) noexcept { move_from(o); }
CanSocket& CanSocket::operator=(CanSocket&& o) noexcept {
  if (this != &o) {
    close();
    move_from(o);
  }
  return *this;
}
void CanSocket::move_from(CanSocket& o) noexcept {
  fd_ = std::exchange(o.fd_, -1);
  state_ = o.state_;
  error_frames_ = o.error_frames_;
  batch_ = o.batch_;
  batch_length_ = o.batch_length_;
  batch_count_ = std::exchange(o.batch_count_, 0);
  batch_next_ = std::exchange(o.batch_next_, 0);
}
void CanSocket::close() noexcept {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  batch_count_ = batch_next_ = 0;
}

bool CanSocket::fill(bool& failed) noexcept {
  static_assert(sizeof(can_frame) == kFrameBytes);
  failed = false;
  std::array<iovec, kBatch> iov{};
  std::array<mmsghdr, kBatch> msgs{};
  for (std::size_t i = 0; i < kBatch; ++i) {
    iov[i] = {batch_[i].data(), kFrameBytes};
    msgs[i].msg_hdr.msg_iov = &iov[i];
    msgs[i].msg_hdr.msg_iovlen = 1;
  }
  const int n = ::recvmmsg(fd_, msgs.data(), kBatch, MSG_DONTWAIT, nullptr);
  if (n < 0) {
    failed = !(errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR);
    return false;
  }
  if (n == 0) {
    failed = true;  // the peer closed (a socketpair)
    return false;
  }
  for (int i = 0; i < n; ++i) batch_length_[static_cast<std::size_t>(i)] = msgs[static_cast<std::size_t>(i)].msg_len;
  batch_count_ = static_cast<std::size_t>(n);
  batch_next_ = 0;
  return true;
}

ReceiveStatus CanSocket::receive(RawFrame& out) noexcept {
  if (fd_ < 0) return ReceiveStatus::kFailed;
  if (batch_next_ == batch_count_) {
    bool failed = false;
    if (!fill(failed)) return failed ? ReceiveStatus::kFailed : ReceiveStatus::kEmpty;
  }
  const std::size_t slot = batch_next_++;
  const std::uint32_t n = batch_length_[slot];
  if (n == 0) {
    batch_count_ = batch_next_ = 0;
    return ReceiveStatus::kFailed;  // the peer closed (a socketpair)
  }
  can_frame f{};
  std::memcpy(&f, batch_[slot].data(), sizeof f);
  if (n != sizeof f) return ReceiveStatus::kBadFrame;
  if ((f.can_id & CAN_ERR_FLAG) != 0U) {
    ++error_frames_;
    if ((f.can_id & CAN_ERR_BUSOFF) != 0U) {
      state_ = BusState::kBusOff;
    } else if ((f.can_id & CAN_ERR_RESTARTED) != 0U) {
      state_ = BusState::kActive;
    } else if ((f.can_id & CAN_ERR_CRTL) != 0U) {
      const std::uint8_t c = f.data[1];
      if ((c & (CAN_ERR_CRTL_RX_PASSIVE | CAN_ERR_CRTL_TX_PASSIVE)) != 0U) {
        state_ = BusState::kErrorPassive;
      } else if ((c & CAN_ERR_CRTL_ACTIVE) != 0U) {
        state_ = BusState::kActive;
      }
    }
    return ReceiveStatus::kErrorFrame;
  }
  if ((f.can_id & (CAN_EFF_FLAG | CAN_RTR_FLAG)) != 0U || f.len > 8) return ReceiveStatus::kBadFrame;
  out.id = f.can_id & CAN_SFF_MASK;
  out.length = f.len;
  std::memcpy(out.data.data(), f.data, 8);
  for (std::size_t i = f.len; i < 8; ++i) out.data[i] = 0;
  return ReceiveStatus::kFrame;
}

SendStatus CanSocket::send(const RawFrame& frame) noexcept {
  if (fd_ < 0) return SendStatus::kFailed;
  can_frame f{};
  f.can_id = frame.id & CAN_SFF_MASK;
  f.len = frame.length;
  std::memcpy(f.data, frame.data.data(), 8);
  const ssize_t n = ::send(fd_, &f, sizeof f, MSG_DONTWAIT | MSG_NOSIGNAL);
  if (n == static_cast<ssize_t>(sizeof f)) return SendStatus::kSent;
  if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK || errno == ENOBUFS)) return SendStatus::kQueueFull;
  return SendStatus::kFailed;
}

bool send_raw(int fd, std::uint32_t can_id, std::uint8_t length, const std::uint8_t* data) noexcept {
  can_frame f{};
  f.can_id = can_id;
  f.len = length;
  if (data != nullptr) std::memcpy(f.data, data, length > 8 ? 8 : length);
  return ::send(fd, &f, sizeof f, MSG_DONTWAIT | MSG_NOSIGNAL) == static_cast<ssize_t>(sizeof f);
}

bool send_error_frame(int fd, BusState state, bool restarted) noexcept {
  std::uint8_t data[8]{};
  std::uint32_t id = CAN_ERR_FLAG;
  if (restarted) {
    id |= CAN_ERR_RESTARTED;
  } else if (state == BusState::kBusOff) {
    id |= CAN_ERR_BUSOFF;
  } else {
    id |= CAN_ERR_CRTL;
    data[1] = state == BusState::kErrorPassive ? (CAN_ERR_CRTL_RX_PASSIVE | CAN_ERR_CRTL_TX_PASSIVE) : CAN_ERR_CRTL_ACTIVE;
  }
  return send_raw(fd, id, CAN_ERR_DLC, data);
}

}  // namespace ringlet::hal::can
