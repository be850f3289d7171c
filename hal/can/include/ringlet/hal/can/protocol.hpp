#pragma once
// The board's CAN protocol, as one table: every frame's ID, length, direction, rate and signals
// (byte offset, width, signedness, scale, unit, range). The codec below, the DBC file
// (hal/can/ringlet_board.dbc) and the table in hal/can/README.md all come from it
// (ringlet-can-spec), and tests check that the committed DBC and README agree with it.
//
// Classic CAN, 11-bit IDs, at most 8 data bytes. Every signal is byte-aligned and little-endian
// (Intel byte order in DBC terms), so a frame is read the same on every host. A physical value is
// raw · scale; raw values outside [min, max] / scale, and the signal's `no_value` sentinel where
// it has one, mean what the table says, never a silent clamp. Lower IDs win arbitration: the
// safe state and faults come first, then commands, then sensors, the laser last.
#include <array>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace ringlet::hal::can {

enum class Direction : std::uint8_t { kToBoard, kFromBoard };

struct Signal {
  std::string_view name;
  std::uint8_t offset;  // first byte
  std::uint8_t bytes;   // 1, 2, 3 or 4
  bool is_signed;
  double scale;          // physical = raw · scale
  double min, max;       // physical range of a valid value
  std::string_view unit;
  std::optional<std::int64_t> no_value{};  // raw value meaning "not measured" (outside the range)
  std::string_view doc{};
};

struct FrameSpec {
  std::uint32_t id;
  std::string_view name;
  std::uint8_t length;  // exact data length (DLC): a frame of another length is malformed
  Direction direction;
  std::string_view rate;  // e.g. "100 Hz", "on event, then 10 Hz while latched"
  std::string_view doc;
  std::span<const Signal> signals;
};

// ---- IDs ---------------------------------------------------------------------------------------
inline constexpr std::uint32_t kSafeStateId = 0x080;
inline constexpr std::uint32_t kBoardFaultId = 0x090;
inline constexpr std::uint32_t kDriveId = 0x100;
inline constexpr std::uint32_t kHeadCommandId = 0x101;
inline constexpr std::uint32_t kControllerHeartbeatId = 0x110;
inline constexpr std::uint32_t kBoardHeartbeatId = 0x180;
inline constexpr std::uint32_t kPoseId = 0x200;
inline constexpr std::uint32_t kOdometryId = 0x201;
inline constexpr std::uint32_t kHeadJointsId = 0x202;
inline constexpr std::uint32_t kInertialId = 0x203;
inline constexpr std::uint32_t kBumperId = 0x204;
inline constexpr std::uint32_t kPowerId = 0x205;
inline constexpr std::uint32_t kLaserHeaderId = 0x210;
inline constexpr std::uint32_t kLaserRangesId = 0x211;

/// Beams per BOARD_LASER_RANGES frame, and frames per scan of at most 721 beams.
inline constexpr std::size_t kBeamsPerChunk = 3;
inline constexpr std::size_t kMaxLaserChunks = (721 + kBeamsPerChunk - 1) / kBeamsPerChunk;

/// Board and controller states carried by the heartbeats, and the board's fault codes.
enum class ControllerState : std::uint8_t { kStarting = 0, kRunning = 1, kSafe = 2 };
enum class BoardState : std::uint8_t { kBooting = 0, kReady = 1, kDriving = 2, kWatchdogStop = 3, kSafe = 4 };
enum class SafeReason : std::uint8_t { kWatchdog = 1, kPolicy = 2, kOperator = 3, kBoardLost = 4 };
enum class BoardFault : std::uint16_t {
  kCommandTimeout = 1,    // no CTRL_DRIVE within the board's timeout: the car was stopped
  kMotorOvercurrent = 2,  // detail: motor index
  kSensorFailure = 3,     // detail: the ID of the frame the board can no longer fill
  kMalformedCommand = 4,  // detail: the ID of the command frame it refused
  kUndervoltage = 5,      // detail: battery mV
  kBusError = 6,          // detail: the board's transmit error counter
};

/// Every frame of the protocol, in ID order.
std::span<const FrameSpec> frames() noexcept;
/// The spec of an ID, or null when the protocol has no such frame.
const FrameSpec* find_frame(std::uint32_t id) noexcept;

// ---- codec -------------------------------------------------------------------------------------
/// A frame's signals as physical values, in the spec's order (at most 8 signals per frame).
struct Values {
  std::array<double, 8> v{};
  std::array<bool, 8> present{};  // false: the signal carried its no_value sentinel
  [[nodiscard]] double operator[](std::size_t i) const noexcept { return v[i]; }
};

/// Values with every signal present, in the spec's order: values_of({kappa, v, counter, 1}).
Values values_of(std::initializer_list<double> list) noexcept;

/// Raw CAN frame bytes (the payload of a struct can_frame).
struct RawFrame {
  std::uint32_t id = 0;
  std::uint8_t length = 0;
  std::array<std::uint8_t, 8> data{};
};

enum class CodecError : std::uint8_t {
  kNone,
  kUnknownId,     // the protocol has no frame with this ID
  kWrongLength,   // the DLC is not the frame's length
  kOutOfRange,    // a signal's value is outside its range (decode: a raw value; encode: a request)
  kNotFinite,     // encode: NaN or infinity
};

struct CodecResult {
  CodecError error = CodecError::kNone;
  std::uint8_t signal = 0;  // the signal at fault, for kOutOfRange / kNotFinite
  [[nodiscard]] bool ok() const noexcept { return error == CodecError::kNone; }
};

/// Packs `values` (physical, in the spec's order; absent signals get their no_value sentinel)
/// into `out`. Refuses, leaving `out` untouched, a value that is not finite or out of range.
CodecResult encode(const FrameSpec& spec, const Values& values, RawFrame& out) noexcept;
/// Unpacks a received frame. Refuses unknown IDs, wrong lengths and raw values out of range.
CodecResult decode(const RawFrame& in, const FrameSpec*& spec, Values& out) noexcept;

/// "BOARD_ODOMETRY.velocity out of range" and the like, for logs and tests (allocates: not for the cycle).
std::string describe(const RawFrame& frame, const CodecResult& r);

/// The DBC file and the README's Markdown table, written from the table (ringlet-can-spec).
std::string dbc_text();
std::string markdown_table();

}  // namespace ringlet::hal::can
