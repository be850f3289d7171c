#pragma once
// A SocketCAN raw socket, non-blocking, with error frames on: what the board backend reads and
// writes. It carries Linux's `struct can_frame` (16 bytes), whatever the descriptor is: a CAN_RAW
// socket bound to an interface (can0, vcan0), or, in tests, one end of a socketpair.
//
// receive() never blocks: a frame, nothing waiting, or an error frame, which it turns into the
// bus's state (error-passive, bus-off, restarted) and counts. It takes the frames waiting from the
// kernel kBatch at a time (one recvmmsg) and hands them out one by one, in order: a drain of n
// frames costs n / kBatch + 1 system calls, not n + 1 (a laser scan is ~60 frames). send() never blocks either: a full
// transmit queue (EAGAIN / ENOBUFS) is reported so the caller can count it and move on.
#include <array>
#include <cstdint>
#include <string>
#include <string_view>

#include "ringlet/hal/board_health.hpp"
#include "ringlet/hal/can/protocol.hpp"

namespace ringlet::hal::can {

using hal::BusState;

enum class ReceiveStatus : std::uint8_t {
  kFrame,       // `out` holds a data frame
  kEmpty,       // nothing waiting
  kErrorFrame,  // an error frame: state() may have changed
  kBadFrame,    // a frame the protocol cannot carry (extended or remote frame, DLC > 8, short read)
  kFailed,      // the socket failed (the interface went down): reopen
};

enum class SendStatus : std::uint8_t { kSent, kQueueFull, kFailed };

class CanSocket {
 public:
  CanSocket() = default;
  /// A CAN_RAW socket on `interface`, non-blocking, receiving error frames. On failure the socket
  /// is closed and, when `error` is given, it says why (no such interface, no CAN support in the
  /// kernel, ...). Without `error` nothing is allocated: CanRobot reopens from the sense task.
  static CanSocket open(std::string_view interface, std::string* error = nullptr);
  /// Takes a descriptor that carries struct can_frame (e.g. a socketpair end) and makes it
  /// non-blocking.
  static CanSocket adopt(int fd) noexcept;
  ~CanSocket();
  CanSocket(CanSocket&& o) noexcept;
  CanSocket& operator=(CanSocket&& o) noexcept;
  CanSocket(const CanSocket&) = delete;
  CanSocket& operator=(const CanSocket&) = delete;

  [[nodiscard]] bool is_open() const noexcept { return fd_ >= 0; }
  [[nodiscard]] int fd() const noexcept { return fd_; }

  ReceiveStatus receive(RawFrame& out) noexcept;
  SendStatus send(const RawFrame& frame) noexcept;

  [[nodiscard]] BusState state() const noexcept { return state_; }
  /// The controller said it restarted after a bus-off (CAN_ERR_RESTARTED), or an error frame
  /// that reports no error-passive or bus-off came after one: the bus is active again.
  [[nodiscard]] std::uint64_t error_frames() const noexcept { return error_frames_; }

 private:
  explicit CanSocket(int fd) noexcept : fd_(fd) {}
  void close() noexcept;
  void move_from(CanSocket& o) noexcept;
  /// Fills the batch from the kernel: false when nothing is waiting or the socket failed (`failed`).
  bool fill(bool& failed) noexcept;

  static constexpr std::size_t kBatch = 32;
  static constexpr std::size_t kFrameBytes = 16;  // sizeof(struct can_frame)
  int fd_ = -1;
  // Frames taken from the kernel and not yet handed out: [batch_next_, batch_count_).
  std::array<std::array<unsigned char, kFrameBytes>, kBatch> batch_{};
  std::array<std::uint32_t, kBatch> batch_length_{};
  std::size_t batch_count_ = 0;
  std::size_t batch_next_ = 0;
  BusState state_ = BusState::kActive;
  std::uint64_t error_frames_ = 0;
};

/// Sends an error frame, the way the CAN driver does, on a descriptor (tests: the other end of
/// a socketpair).
bool send_error_frame(int fd, BusState state, bool restarted = false) noexcept;
/// Sends a raw struct can_frame with the given ID flags and length (tests: malformed frames).
bool send_raw(int fd, std::uint32_t can_id, std::uint8_t length, const std::uint8_t* data) noexcept;

}  // namespace ringlet::hal::can
