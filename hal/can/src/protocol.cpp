#include "ringlet/hal/can/protocol.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace ringlet::hal::can {
namespace {

using D = Direction;
constexpr double kPi = 3.14159265358979323846;

// ---- the table ---------------------------------------------------------------------------------
constexpr Signal kSafeState[] = {
    {"reason", 0, 1, false, 1, 1, 4, "", {}, "1 watchdog, 2 overrun policy, 3 operator, 4 board heartbeat lost"},
};
constexpr Signal kBoardFault[] = {
    {"code", 0, 2, false, 1, 1, 6, "", {}, "1 command timeout, 2 motor overcurrent, 3 sensor failure, 4 malformed command, 5 undervoltage, 6 bus error"},
    {"detail", 2, 2, false, 1, 0, 65535, "", {}, "per code (protocol.hpp BoardFault)"},
};
constexpr Signal kDrive[] = {
    {"curvature", 0, 2, true, 0.001, -20, 20, "1/m", {}, "kappa of eq. 17, positive turns clockwise"},
    {"velocity", 2, 2, true, 0.001, -5, 5, "m/s", {}, "v of eq. 17"},
    {"counter", 4, 1, false, 1, 0, 255, "", {}, "+1 per frame: the board sees lost or repeated commands"},
    {"enable", 5, 1, false, 1, 0, 1, "", {}, "0: stop (motors braked)"},
};
constexpr Signal kHeadCommand[] = {
    {"yaw", 0, 2, true, 0.0001, -kPi, kPi, "rad", {}, "positive left; the board clamps to its joint limits"},
    {"pitch", 2, 2, true, 0.0001, -kPi / 2, kPi / 2, "rad", {}, "positive down"},
};
constexpr Signal kControllerHeartbeat[] = {
    {"counter", 0, 1, false, 1, 0, 255, "", {}, "+1 per frame"},
    {"state", 1, 1, false, 1, 0, 2, "", {}, "0 starting, 1 running, 2 safe state"},
};
constexpr Signal kBoardHeartbeat[] = {
    {"counter", 0, 1, false, 1, 0, 255, "", {}, "+1 per frame"},
    {"state", 1, 1, false, 1, 0, 4, "", {}, "0 booting, 1 ready, 2 driving, 3 stopped by its watchdog, 4 safe state"},
    {"faults", 2, 2, false, 1, 0, 65535, "", {}, "faults since power-on"},
    {"drive", 4, 1, false, 1, 0, 255, "", {}, "the counter of the last CTRL_DRIVE applied before this step's sensor frames: the controller's command -> board -> sensor round trip"},
};
constexpr Signal kPose[] = {
    {"x", 0, 3, true, 0.001, -8388.607, 8388.607, "m", -8388608, "world frame; raw -8388608 in x and y: no fix"},
    {"y", 3, 3, true, 0.001, -8388.607, 8388.607, "m", -8388608, "world frame"},
    {"theta", 6, 2, true, 0.0001, -kPi, kPi, "rad", {}, "from +y towards +x"},
};
constexpr Signal kOdometry[] = {
    {"distance", 0, 4, true, 0.0001, -214748.3647, 214748.3647, "m", {}, "integrated since power-on, signed"},
    {"velocity", 4, 2, true, 0.001, -5, 5, "m/s", {}, "measured v"},
    {"curvature", 6, 2, true, 0.001, -32.767, 32.767, "1/m", {}, "measured kappa"},
};
constexpr Signal kHeadJoints[] = {
    {"yaw", 0, 2, true, 0.0001, -kPi, kPi, "rad", {}, "measured, positive left"},
    {"pitch", 2, 2, true, 0.0001, -kPi / 2, kPi / 2, "rad", {}, "measured, positive down"},
};
constexpr Signal kInertial[] = {
    {"pitch", 0, 2, true, 0.0001, -kPi / 2, kPi / 2, "rad", -32768, "torso tilt, positive forward; raw -32768: no reading"},
    {"roll", 2, 2, true, 0.0001, -kPi / 2, kPi / 2, "rad", -32768, "torso tilt, positive leaning right"},
};
constexpr Signal kBumper[] = {
    {"contact", 0, 1, false, 1, 0, 1, "", {}, "1: touching an obstacle now"},
};
constexpr Signal kPower[] = {
    {"battery", 0, 2, false, 0.001, 0, 65.535, "V", {}, ""},
    {"bus", 2, 2, false, 0.001, 0, 65.535, "V", {}, "motor bus"},
};
constexpr Signal kLaserHeader[] = {
    {"scan", 0, 1, false, 1, 0, 255, "", {}, "+1 per scan; the range frames that follow carry it"},
    {"beams", 1, 2, false, 1, 1, 721, "", {}, "beam count"},
    {"angle_min", 3, 2, true, 0.0001, -kPi, kPi, "rad", {}, "first beam, positive right"},
    {"angle_increment", 5, 2, true, 0.00001, -0.32767, 0.32767, "rad", {}, ""},
    {"max_range", 7, 1, false, 0.1, 0.1, 25.5, "m", {}, "Delta"},
};
constexpr Signal kLaserRanges[] = {
    {"scan", 0, 1, false, 1, 0, 255, "", {}, "the header's scan"},
    {"chunk", 1, 1, false, 1, 0, kMaxLaserChunks - 1, "", {}, "beams 3·chunk to 3·chunk+2"},
    {"range0", 2, 2, false, 0.001, 0.001, 65.535, "m", 0, "raw 0: nothing seen (phi)"},
    {"range1", 4, 2, false, 0.001, 0.001, 65.535, "m", 0, ""},
    {"range2", 6, 2, false, 0.001, 0.001, 65.535, "m", 0, ""},
};

constexpr FrameSpec kFrames[] = {
    {kSafeStateId, "CTRL_SAFE_STATE", 1, D::kToBoard, "on event, then 10 Hz while latched",
     "stop the car and hold the head now; latched until the board restarts", kSafeState},
    {kBoardFaultId, "BOARD_FAULT", 4, D::kFromBoard, "on event", "a fault the board detected", kBoardFault},
    {kDriveId, "CTRL_DRIVE", 6, D::kToBoard, "100 Hz (actuate)",
     "u = (kappa, v); the board stops the car when none arrives for its timeout (100 ms)", kDrive},
    {kHeadCommandId, "CTRL_HEAD", 4, D::kToBoard, "100 Hz (actuate)", "head target", kHeadCommand},
    {kControllerHeartbeatId, "CTRL_HEARTBEAT", 2, D::kToBoard, "10 Hz", "the controller is alive", kControllerHeartbeat},
    {kBoardHeartbeatId, "BOARD_HEARTBEAT", 5, D::kFromBoard, "10 Hz",
     "the board is alive; the controller enters the safe state after [can] heartbeat_timeout_ms without one",
     kBoardHeartbeat},
    {kPoseId, "BOARD_POSE", 8, D::kFromBoard, "100 Hz", "y = (x, y, theta) of eq. 19", kPose},
    {kOdometryId, "BOARD_ODOMETRY", 8, D::kFromBoard, "100 Hz", "wheel odometry", kOdometry},
    {kHeadJointsId, "BOARD_HEAD", 4, D::kFromBoard, "100 Hz", "head joint angles", kHeadJoints},
    {kInertialId, "BOARD_IMU", 4, D::kFromBoard, "100 Hz", "the inertial unit's torso tilt", kInertial},
    {kBumperId, "BOARD_BUMPER", 1, D::kFromBoard, "100 Hz", "the base's bumper", kBumper},
    {kPowerId, "BOARD_POWER", 4, D::kFromBoard, "1 Hz", "battery and motor bus voltage", kPower},
    {kLaserHeaderId, "BOARD_LASER_HEADER", 8, D::kFromBoard, "10 Hz", "a planar scan (eq. 20) begins", kLaserHeader},
    {kLaserRangesId, "BOARD_LASER_RANGES", 8, D::kFromBoard, "10 Hz × 241 frames",
     "three beams of the scan, in chunk order", kLaserRanges},
};

std::int64_t read_raw(const std::array<std::uint8_t, 8>& data, const Signal& s) noexcept {
  std::uint64_t u = 0;
  for (int b = s.bytes - 1; b >= 0; --b) u = (u << 8) | data[static_cast<std::size_t>(s.offset + b)];
  if (s.is_signed && (u >> (8 * s.bytes - 1)) != 0U) {
    return static_cast<std::int64_t>(u) - (std::int64_t{1} << (8 * s.bytes));
  }
  return static_cast<std::int64_t>(u);
}

void write_raw(std::array<std::uint8_t, 8>& data, const Signal& s, std::int64_t raw) noexcept {
  auto u = static_cast<std::uint64_t>(raw);
  for (int b = 0; b < s.bytes; ++b) {
    data[static_cast<std::size_t>(s.offset + b)] = static_cast<std::uint8_t>(u & 0xFFU);
    u >>= 8;
  }
}

// The raw range of a valid value (physical range / scale, rounded inwards).
std::int64_t raw_min(const Signal& s) noexcept { return static_cast<std::int64_t>(std::ceil(s.min / s.scale - 1e-9)); }
std::int64_t raw_max(const Signal& s) noexcept { return static_cast<std::int64_t>(std::floor(s.max / s.scale + 1e-9)); }

}  // namespace

std::span<const FrameSpec> frames() noexcept { return kFrames; }

Values values_of(std::initializer_list<double> list) noexcept {
  Values v;
  std::size_t i = 0;
  for (const double x : list) {
    if (i == v.v.size()) break;
    v.v[i] = x;
    v.present[i++] = true;
  }
  return v;
}

const FrameSpec* find_frame(std::uint32_t id) noexcept {
  for (const FrameSpec& f : kFrames) {
    if (f.id == id) return &f;
  }
  return nullptr;
}

CodecResult encode(const FrameSpec& spec, const Values& values, RawFrame& out) noexcept {
  RawFrame f;
  f.id = spec.id;
  f.length = spec.length;
  for (std::size_t i = 0; i < spec.signals.size(); ++i) {
    const Signal& s = spec.signals[i];
    const auto index = static_cast<std::uint8_t>(i);
    if (!values.present[i]) {
      if (!s.no_value) return {CodecError::kOutOfRange, index};  // this signal must carry a value
      write_raw(f.data, s, *s.no_value);
      continue;
    }
    if (!std::isfinite(values.v[i])) return {CodecError::kNotFinite, index};
    if (values.v[i] < s.min || values.v[i] > s.max) return {CodecError::kOutOfRange, index};
    // Inside the range, rounding to the scale may step just past a range end (pi / 0.0001): keep
    // the nearest raw value inside it.
    const auto r = static_cast<std::int64_t>(std::round(values.v[i] / s.scale));
    write_raw(f.data, s, std::clamp(r, raw_min(s), raw_max(s)));
  }
  out = f;
  return {};
}

CodecResult decode(const RawFrame& in, const FrameSpec*& spec, Values& out) noexcept {
  spec = find_frame(in.id);
  if (spec == nullptr) return {CodecError::kUnknownId, 0};
  if (in.length != spec->length) return {CodecError::kWrongLength, 0};
  Values v;
  for (std::size_t i = 0; i < spec->signals.size(); ++i) {
    const Signal& s = spec->signals[i];
    const std::int64_t raw = read_raw(in.data, s);
    if (s.no_value && raw == *s.no_value) continue;  // present stays false
    if (raw < raw_min(s) || raw > raw_max(s)) return {CodecError::kOutOfRange, static_cast<std::uint8_t>(i)};
    v.v[i] = static_cast<double>(raw) * s.scale;
    v.present[i] = true;
  }
  out = v;
  return {};
}

std::string describe(const RawFrame& frame, const CodecResult& r) {
  char id[16];
  std::snprintf(id, sizeof id, "0x%03X", static_cast<unsigned>(frame.id));
  const FrameSpec* spec = find_frame(frame.id);
  const std::string name = spec ? std::string(spec->name) + " (" + id + ")" : std::string("ID ") + id;
  const auto signal = [&] {
    return spec && r.signal < spec->signals.size() ? std::string(spec->name) + "." + std::string(spec->signals[r.signal].name)
                                                   : name;
  };
  switch (r.error) {
    case CodecError::kNone: return name + ": ok";
    case CodecError::kUnknownId: return name + ": not a frame of the protocol";
    case CodecError::kWrongLength:
      return name + ": " + std::to_string(frame.length) + " data bytes, the protocol says " + std::to_string(spec->length);
    case CodecError::kOutOfRange: return signal() + ": value out of range";
    case CodecError::kNotFinite: return signal() + ": not a finite number";
  }
  return name;
}

std::string dbc_text() {
  std::string out =
      "VERSION \"ringlet board 1\"\n\nNS_ :\n\nBS_:\n\nBU_: Controller Board\n\n";
  char line[512];
  for (const FrameSpec& f : kFrames) {
    std::snprintf(line, sizeof line, "BO_ %u %.*s: %u %s\n", static_cast<unsigned>(f.id), static_cast<int>(f.name.size()),
                  f.name.data(), static_cast<unsigned>(f.length), f.direction == D::kToBoard ? "Controller" : "Board");
    out += line;
    for (const Signal& s : f.signals) {
      std::snprintf(line, sizeof line, " SG_ %.*s : %u|%u@1%c (%.10g,0) [%.10g|%.10g] \"%.*s\" %s\n",
                    static_cast<int>(s.name.size()), s.name.data(), static_cast<unsigned>(8 * s.offset),
                    static_cast<unsigned>(8 * s.bytes), s.is_signed ? '-' : '+', s.scale, s.min, s.max,
                    static_cast<int>(s.unit.size()), s.unit.data(), f.direction == D::kToBoard ? "Board" : "Controller");
      out += line;
    }
    out += "\n";
  }
  for (const FrameSpec& f : kFrames) {
    std::snprintf(line, sizeof line, "CM_ BO_ %u \"%.*s (%.*s)\";\n", static_cast<unsigned>(f.id), static_cast<int>(f.doc.size()),
                  f.doc.data(), static_cast<int>(f.rate.size()), f.rate.data());
    out += line;
    for (const Signal& s : f.signals) {
      if (s.doc.empty()) continue;
      std::snprintf(line, sizeof line, "CM_ SG_ %u %.*s \"%.*s\";\n", static_cast<unsigned>(f.id), static_cast<int>(s.name.size()),
                    s.name.data(), static_cast<int>(s.doc.size()), s.doc.data());
      out += line;
    }
  }
  return out;
}

std::string markdown_table() {
  std::string out =
      "| ID | frame | bytes | from | rate | signal: byte offset, width, scale, range, unit | meaning |\n"
      "|---|---|---|---|---|---|---|\n";
  char buf[512];
  for (const FrameSpec& f : kFrames) {
    std::string signals;
    for (const Signal& s : f.signals) {
      std::snprintf(buf, sizeof buf, "%s`%.*s` @%u %s%u ×%.10g [%.10g, %.10g]%s%.*s%s", signals.empty() ? "" : "<br>",
                    static_cast<int>(s.name.size()), s.name.data(), static_cast<unsigned>(s.offset), s.is_signed ? "i" : "u",
                    static_cast<unsigned>(8 * s.bytes), s.scale, s.min, s.max, s.unit.empty() ? "" : " ",
                    static_cast<int>(s.unit.size()), s.unit.data(),
                    s.doc.empty() ? "" : (": " + std::string(s.doc)).c_str());
      signals += buf;
    }
    std::snprintf(buf, sizeof buf, "| 0x%03X | `%.*s` | %u | %s | %.*s | ", static_cast<unsigned>(f.id),
                  static_cast<int>(f.name.size()), f.name.data(), static_cast<unsigned>(f.length),
                  f.direction == D::kToBoard ? "controller" : "board", static_cast<int>(f.rate.size()), f.rate.data());
    out += buf + signals + " | " + std::string(f.doc) + " |\n";
  }
  return out;
}

}  // namespace ringlet::hal::can
