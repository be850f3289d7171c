#include "ringlet/hal/robot_log_reader.hpp"

#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <string>
#include <system_error>

#include "le_bytes.hpp"
#include "ringlet/hal/read_file.hpp"

namespace ringlet::hal {
namespace {

std::string errno_text(int err) { return std::generic_category().message(err); }

constexpr std::size_t kFileBufferBytes = 64 * 1024;
constexpr std::size_t kHeaderFixedBytes = 24;  // magic, version, period, note length
constexpr std::size_t kMaxSmallPayload = kMaxSensorRecordBytes - kRecordHeaderBytes;

}  // namespace

struct RobotLogReader::Impl {
  std::filesystem::path path;
  std::string name;
  LogReaderOptions options;
  InputFile file;
  std::uint64_t file_size = 0;  // at open
  std::uint64_t offset = 0;  // of the next byte the reader hands out
  std::vector<std::uint8_t> buffer = std::vector<std::uint8_t>(kFileBufferBytes);
  std::size_t buffered_begin = 0;
  std::size_t buffered_end = 0;
  std::array<std::uint8_t, kMaxSmallPayload> payload{};
  LogHeader header;
  std::uint64_t reads = 0;
  std::uint64_t dropped = 0;
  bool saw_end = false;
  std::uint64_t torn = 0;

  [[noreturn]] void fail(const std::string& what, std::uint64_t at) const {
    throw LogError(name + ": " + what + " at byte " + std::to_string(at));
  }
  [[noreturn]] void fail_open(const std::string& why) const {
    throw LogError(name + ": cannot read HAL log: " + why);
  }

  [[nodiscard]] std::uint64_t left() const noexcept { return file_size > offset ? file_size - offset : 0; }

  /// Copies up to n bytes; returns how many (fewer only at the end of the file).
  std::size_t read_up_to(std::uint8_t* dst, std::size_t n) {
    std::size_t got = 0;
    while (got < n) {
      if (buffered_begin == buffered_end) {
        const ssize_t r = ::read(file.fd(), buffer.data(), buffer.size());
        if (r < 0) {
          if (errno == EINTR) continue;
          fail("cannot read: " + errno_text(errno), offset);
        }
        if (r == 0) break;
        buffered_begin = 0;
        buffered_end = static_cast<std::size_t>(r);
      }
      const std::size_t take = std::min(n - got, buffered_end - buffered_begin);
      std::memcpy(dst + got, buffer.data() + buffered_begin, take);
      buffered_begin += take;
      got += take;
      offset += take;
    }
    return got;
  }

  void read_exact(std::uint8_t* dst, std::size_t n, const char* what, std::uint64_t record_at) {
    const std::size_t got = read_up_to(dst, n);
    if (got < n) {
      fail(std::string("truncated ") + what + " (" + std::to_string(n) + " bytes needed, " +
               std::to_string(got) + " left)",
           record_at);
    }
  }

  void skip(std::uint64_t n) {
    const std::size_t in_buffer = buffered_end - buffered_begin;
    if (n <= in_buffer) {
      buffered_begin += static_cast<std::size_t>(n);
      offset += n;
      return;
    }
    const std::uint64_t beyond = n - in_buffer;
    buffered_begin = buffered_end = 0;
    if (::lseek(file.fd(), static_cast<off_t>(beyond), SEEK_CUR) < 0) fail("cannot seek: " + errno_text(errno), offset);
    offset += n;
  }

  void open() {
    if (std::string refused = file.open(path); !refused.empty()) fail_open(refused);
    file_size = file.size();
    read_header();
  }

  void read_header() {
    std::array<std::uint8_t, kHeaderFixedBytes> h{};
    const std::size_t got = read_up_to(h.data(), h.size());
    const std::size_t magic_got = std::min(got, kRobotLogMagic.size());
    if (std::memcmp(h.data(), kRobotLogMagic.data(), magic_got) != 0) {
      fail("wrong magic (not a Ringlet HAL log)", 0);
    }
    if (got < h.size()) {
      fail("truncated header (" + std::to_string(h.size()) + " bytes needed, " + std::to_string(got) + " left)", 0);
    }
    LeReader r{h.data() + kRobotLogMagic.size()};
    header.version = r.u32();
    if (header.version != kRobotLogVersion) {
      // Version 1 logs predate the inertial unit: say so, since "record it again" is the remedy.
      fail("unsupported version " + std::to_string(header.version) + " (this build reads version " +
               std::to_string(kRobotLogVersion) +
               (header.version == 1 ? "; version 1 logs have no torso tilt, record the run again" : "") + ")",
           8);
    }
    const std::int64_t period = r.i64();
    if (period <= 0) fail("period of " + std::to_string(period) + " ns is not positive", 12);
    header.period = Nanos{period};
    const std::uint32_t note = r.u32();
    if (note > kMaxLogNoteBytes) {
      fail("note of " + std::to_string(note) + " bytes is longer than the limit of " +
               std::to_string(kMaxLogNoteBytes),
           20);
    }
    header.note.resize(note);
    read_exact(reinterpret_cast<std::uint8_t*>(header.note.data()), note, "header note", 20);
  }

  bool read_bool(LeReader& r, const char* field, std::uint64_t record_at) const {
    const std::uint64_t at = record_at + kRecordHeaderBytes + static_cast<std::uint64_t>(r.position() - payload.data());
    const std::uint8_t v = r.u8();
    if (v > 1) fail(std::string(field) + " is " + std::to_string(v) + ", not 0 or 1", at);
    return v == 1;
  }

  void expect_size(RecordKind kind, std::uint32_t size, std::size_t expected, std::uint64_t at) const {
    if (size != expected) {
      fail(std::string(to_string(kind)) + " record of " + std::to_string(size) + " bytes, expected " +
               std::to_string(expected),
           at);
    }
  }

  void expect_reads(RecordKind kind, std::uint64_t tag, std::uint64_t at) const {
    if (tag != reads) {
      fail(std::string(to_string(kind)) + " record tagged with read " + std::to_string(tag) + ", expected " +
               std::to_string(reads),
           at);
    }
  }

  /// Reads a fixed-size payload into `payload`; false at a tolerated torn tail.
  bool load_payload(RecordKind kind, std::uint32_t size, std::uint64_t at) {
    if (size > left()) return torn_or_fail(kind, size, at);
    read_exact(payload.data(), size, (std::string(to_string(kind)) + " record").c_str(), at);
    return true;
  }

  bool torn_or_fail(RecordKind kind, std::uint64_t size, std::uint64_t at) {
    if (options.tolerate_torn_tail) {
      torn = size_or_left(at);
      return false;
    }
    fail(std::string("truncated ") + to_string(kind) + " record (" + std::to_string(size) + " bytes announced, " +
             std::to_string(left()) + " left)",
         at);
  }
  std::uint64_t size_or_left(std::uint64_t at) const noexcept { return file_size > at ? file_size - at : 0; }

  bool next(LogRecord& out, std::vector<std::uint8_t>* pixels) {
    const std::uint64_t at = offset;
    std::array<std::uint8_t, kRecordHeaderBytes> h{};
    const std::size_t got = read_up_to(h.data(), h.size());
    if (got == 0) return false;
    if (saw_end) fail("data after the end record", at);
    if (got < h.size()) {
      if (options.tolerate_torn_tail) {
        torn = got;
        return false;
      }
      fail("truncated record header (5 bytes needed, " + std::to_string(got) + " left)", at);
    }
    LeReader hr{h.data()};
    const std::uint8_t raw_kind = hr.u8();
    const std::uint32_t size = hr.u32();
    if (raw_kind < 1 || raw_kind > 5) fail("unknown record kind " + std::to_string(raw_kind), at);
    const auto kind = static_cast<RecordKind>(raw_kind);
    out.kind = kind;
    out.offset = at;
    switch (kind) {
      case RecordKind::kSensor: return read_sensor(out.sensor, size, at);
      case RecordKind::kBall: return read_ball(out.ball, size, at);
      case RecordKind::kCamera: return read_camera(out.camera, size, at, pixels);
      case RecordKind::kGap: return read_gap(out.gap, size, at);
      case RecordKind::kEnd: return read_end(out.end, size, at);
    }
    return false;
  }

  bool read_sensor(SensorRecord& s, std::uint32_t size, std::uint64_t at) {
    if (size < kSensorFixedBytes || size > kMaxSmallPayload || (size - kSensorFixedBytes) % kBytesPerBeam != 0) {
      fail("sensor record of " + std::to_string(size) + " bytes is not " + std::to_string(kSensorFixedBytes) +
               " + 5 per beam for 0 to " + std::to_string(LaserScan::kMaxBeams) + " beams",
           at);
    }
    if (!load_payload(RecordKind::kSensor, size, at)) return false;
    LeReader r{payload.data()};
    s.index = r.u64();
    if (s.index != reads) {
      fail("sensor record index " + std::to_string(s.index) + ", expected " + std::to_string(reads), at);
    }
    s.ok = read_bool(r, "sensor record: ok", at);
    SensorFrame& f = s.frame;
    f.stamp = Nanos{r.i64()};
    f.pose.stamp = Nanos{r.i64()};
    f.pose.pose.x = r.f64();
    f.pose.pose.y = r.f64();
    f.pose.pose.theta = r.f64();
    f.pose.valid = read_bool(r, "sensor record: pose.valid", at);
    f.odometry.stamp = Nanos{r.i64()};
    f.odometry.distance = r.f64();
    f.odometry.velocity = r.f64();
    f.odometry.curvature = r.f64();
    f.head.yaw = r.f64();
    f.head.pitch = r.f64();
    f.body.stamp = Nanos{r.i64()};
    f.body.tilt.pitch = r.f64();
    f.body.tilt.roll = r.f64();
    f.body.valid = read_bool(r, "sensor record: body.valid", at);
    f.power.battery_volts = r.f64();
    f.power.bus_volts = r.f64();
    f.laser.stamp = Nanos{r.i64()};
    const std::uint64_t beams_at = at + kRecordHeaderBytes + static_cast<std::uint64_t>(r.position() - payload.data());
    const std::uint16_t beams = r.u16();
    if (beams > LaserScan::kMaxBeams) {
      fail("laser beam_count " + std::to_string(beams) + " exceeds " + std::to_string(LaserScan::kMaxBeams), beams_at);
    }
    if (size != kSensorFixedBytes + kBytesPerBeam * beams) {
      fail("sensor record of " + std::to_string(size) + " bytes does not match its " + std::to_string(beams) +
               " beams (" + std::to_string(kSensorFixedBytes + kBytesPerBeam * beams) + " expected)",
           at);
    }
    f.laser.beam_count = beams;
    f.laser.angle_min = r.f64();
    f.laser.angle_increment = r.f64();
    f.laser.max_range = r.f64();
    f.collided = read_bool(r, "sensor record: collided", at);
    for (std::size_t i = 0; i < beams; ++i) {
      f.laser.range[i] = r.f32();
      f.laser.valid[i] = read_bool(r, "sensor record: laser.valid", at);
    }
    for (std::size_t i = beams; i < LaserScan::kMaxBeams; ++i) {
      f.laser.range[i] = 0.0F;
      f.laser.valid[i] = false;
    }
    reads = s.index + 1;
    return true;
  }

  bool read_ball(BallRecord& b, std::uint32_t size, std::uint64_t at) {
    expect_size(RecordKind::kBall, size, kBallPayloadBytes, at);
    if (!load_payload(RecordKind::kBall, size, at)) return false;
    LeReader r{payload.data()};
    b.reads = r.u64();
    expect_reads(RecordKind::kBall, b.reads, at);
    b.ok = read_bool(r, "ball record: ok", at);
    b.sighting.stamp = Nanos{r.i64()};
    b.sighting.seen = read_bool(r, "ball record: seen", at);
    b.sighting.at.x = r.f64();
    b.sighting.at.y = r.f64();
    return true;
  }

  bool read_camera(CameraRecord& c, std::uint32_t size, std::uint64_t at, std::vector<std::uint8_t>* pixels) {
    if (size < kCameraFixedBytes) {
      fail("camera record of " + std::to_string(size) + " bytes is shorter than its " +
               std::to_string(kCameraFixedBytes) + "-byte header",
           at);
    }
    if (size > kCameraFixedBytes + kMaxLogCameraFrameBytes) {
      fail("camera record of " + std::to_string(size) + " bytes is larger than the largest frame (" +
               std::to_string(kMaxLogCameraFrameBytes) + " bytes)",
           at);
    }
    if (size > left()) return torn_or_fail(RecordKind::kCamera, size, at);
    read_exact(payload.data(), kCameraFixedBytes, "camera record", at);
    LeReader r{payload.data()};
    c.reads = r.u64();
    expect_reads(RecordKind::kCamera, c.reads, at);
    c.capture_time = Nanos{r.i64()};
    c.sequence = r.u64();
    const std::uint8_t format = r.u8();
    if (format > static_cast<std::uint8_t>(PixelFormat::kGray8)) {
      fail("camera record: unknown pixel format " + std::to_string(format), at);
    }
    c.format = static_cast<PixelFormat>(format);
    c.width = r.u32();
    c.height = r.u32();
    c.stride = r.u32();
    const std::uint64_t pixels_count = std::uint64_t{c.width} * c.height;
    if (c.width == 0 || c.height == 0 || pixels_count > kMaxImagePixels) {
      fail("camera frame " + std::to_string(c.width) + "x" + std::to_string(c.height) +
               " is empty or exceeds " + std::to_string(kMaxImagePixels) + " pixels",
           at);
    }
    const std::uint64_t row = std::uint64_t{c.width} * bytes_per_pixel(c.format);
    if (c.stride < row) {
      fail("camera frame stride " + std::to_string(c.stride) + " is less than a row (" + std::to_string(row) +
               " bytes)",
           at);
    }
    const std::uint64_t bytes = std::uint64_t{c.stride} * c.height;
    if (bytes > kMaxLogCameraFrameBytes || size != kCameraFixedBytes + bytes) {
      fail("camera record of " + std::to_string(size) + " bytes does not match its " + std::to_string(c.stride) +
               " x " + std::to_string(c.height) + " pixel bytes",
           at);
    }
    if (pixels == nullptr) {
      skip(bytes);
    } else {
      pixels->resize(static_cast<std::size_t>(bytes));
      read_exact(pixels->data(), pixels->size(), "camera record", at);
    }
    return true;
  }

  bool read_gap(GapRecord& g, std::uint32_t size, std::uint64_t at) {
    expect_size(RecordKind::kGap, size, kGapPayloadBytes, at);
    if (!load_payload(RecordKind::kGap, size, at)) return false;
    LeReader r{payload.data()};
    g.reads = r.u64();
    g.dropped.sensor = r.u32();
    g.dropped.ball = r.u32();
    g.dropped.camera = r.u32();
    if (!g.dropped.any()) fail("gap record drops nothing", at);
    if (g.reads != reads + g.dropped.sensor) {
      fail("gap record tagged with read " + std::to_string(g.reads) + ", expected " +
               std::to_string(reads + g.dropped.sensor) + " (" + std::to_string(g.dropped.sensor) +
               " sensor records dropped)",
           at);
    }
    reads = g.reads;
    dropped += g.dropped.total();
    return true;
  }

  bool read_end(EndRecord& e, std::uint32_t size, std::uint64_t at) {
    expect_size(RecordKind::kEnd, size, kEndPayloadBytes, at);
    if (!load_payload(RecordKind::kEnd, size, at)) return false;
    LeReader r{payload.data()};
    e.sensor_reads = r.u64();
    e.dropped = r.u64();
    if (e.sensor_reads != reads) {
      fail("end record counts " + std::to_string(e.sensor_reads) + " sensor reads, the log has " +
               std::to_string(reads),
           at);
    }
    if (e.dropped != dropped) {
      fail("end record counts " + std::to_string(e.dropped) + " dropped records, the gaps add up to " +
               std::to_string(dropped),
           at);
    }
    saw_end = true;
    return true;
  }
};

RobotLogReader::RobotLogReader(const std::filesystem::path& path, LogReaderOptions options)
    : impl_(std::make_unique<Impl>()) {
  impl_->path = path;
  impl_->name = path.string();
  impl_->options = options;
  impl_->open();
}

RobotLogReader::~RobotLogReader() = default;

const LogHeader& RobotLogReader::header() const noexcept { return impl_->header; }
const std::filesystem::path& RobotLogReader::path() const noexcept { return impl_->path; }
bool RobotLogReader::next(LogRecord& out, std::vector<std::uint8_t>* pixels) { return impl_->next(out, pixels); }
std::uint64_t RobotLogReader::reads() const noexcept { return impl_->reads; }
bool RobotLogReader::saw_end() const noexcept { return impl_->saw_end; }
std::uint64_t RobotLogReader::torn_tail_bytes() const noexcept { return impl_->torn; }
std::uint64_t RobotLogReader::file_bytes() const noexcept { return impl_->file_size; }

RobotLogSummary scan_robot_log(const std::filesystem::path& path, LogReaderOptions options) {
  RobotLogReader reader(path, options);
  RobotLogSummary s;
  s.header = reader.header();
  s.file_bytes = reader.file_bytes();
  LogRecord rec;
  while (reader.next(rec, nullptr)) {
    switch (rec.kind) {
      case RecordKind::kSensor: ++s.sensor_records; break;
      case RecordKind::kBall: ++s.ball_records; break;
      case RecordKind::kCamera:
        ++s.camera_records;
        s.max_camera_frame_bytes = std::max(s.max_camera_frame_bytes, rec.camera.pixel_bytes());
        break;
      case RecordKind::kGap:
        if (s.gap_records == 0) {
          s.first_gap_reads = rec.gap.reads - rec.gap.dropped.sensor;
          s.first_gap_offset = rec.offset;
        }
        ++s.gap_records;
        s.dropped_sensor += rec.gap.dropped.sensor;
        s.dropped_ball += rec.gap.dropped.ball;
        s.dropped_camera += rec.gap.dropped.camera;
        break;
      case RecordKind::kEnd: s.complete = true; break;
    }
  }
  s.sensor_reads = reader.reads();
  s.torn_tail_bytes = reader.torn_tail_bytes();
  return s;
}

}  // namespace ringlet::hal
