#include "ringlet/hal/recording_robot.hpp"

#include <atomic>
#include <chrono>
#include <cstring>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

#include "ringlet/hal/log_file.hpp"
#include "ringlet/hal/spsc_cursor.hpp"

namespace ringlet::hal {
namespace {

// The writer hands the kernel this much at a time (or less when it has caught up).
constexpr std::size_t kFlushBytes = 1u << 20;
// How long the writer sleeps when it has caught up: short enough that a lossless producer waiting
// on a full queue never waits for a sleeping writer (the writer only sleeps on an empty queue).
constexpr auto kIdleSleep = std::chrono::milliseconds{1};

std::uint32_t saturating_inc(std::uint32_t v) noexcept { return v == UINT32_MAX ? v : v + 1; }

}  // namespace

struct RecordingRobot::Impl {
  // One queued record; camera pixels live in the frame ring, in the same order.
  struct Slot {
    RecordKind kind = RecordKind::kSensor;
    bool ok = false;
    std::uint64_t reads = 0;  // sensor: its index; end: all reads
    DropCounts dropped_before{};
    SensorFrame sensor{};
    BallSighting ball{};
    CameraRecord camera{};
  };

  class RecSensors final : public Sensors {
   public:
    explicit RecSensors(Impl& impl) : owner_(impl) {}
    bool read(SensorFrame& reading) noexcept override {
      const bool ok = owner_.inner.sensors().read(reading);
      owner_.record_sensor(ok, reading);
      return ok;
    }

   private:
    Impl& owner_;
  };

  class RecBall final : public BallSensor {
   public:
    RecBall(Impl& impl, BallSensor& inner) : owner_(impl), inner_(inner) {}
    bool read(BallSighting& reading) noexcept override {
      const bool ok = inner_.read(reading);
      owner_.record_ball(ok, reading);
      return ok;
    }

   private:
    Impl& owner_;
    BallSensor& inner_;
  };

  class RecCamera final : public Camera {
   public:
    RecCamera(Impl& impl, Camera& inner) : owner_(impl), inner_(inner) {}
    bool grab_latest(FrameView& reading) noexcept override {
      const bool ok = inner_.grab_latest(reading);
      if (ok && (!have_sequence_ || reading.sequence != last_sequence_)) {
        have_sequence_ = true;
        last_sequence_ = reading.sequence;
        owner_.record_camera(reading);
      }
      return ok;
    }

   private:
    Impl& owner_;
    Camera& inner_;
    bool have_sequence_ = false;
    std::uint64_t last_sequence_ = 0;
  };

  Impl(Robot& inner_robot, const std::filesystem::path& log, RecordingOptions opts)
      : inner(inner_robot),
        path(log.string()),
        file(path, "HAL log"),
        options(std::move(opts)),
        records(options.record_slots),
        frames(options.camera_slots == 0 ? 1 : options.camera_slots),
        sensors(*this) {}

  Robot& inner;
  std::string path;
  LogFile file;
  RecordingOptions options;

  SpscCursor records;
  std::vector<Slot> slots;
  SpscCursor frames;
  std::vector<std::vector<std::uint8_t>> frame_slots;

  RecSensors sensors;
  std::unique_ptr<RecBall> ball;
  std::unique_ptr<RecCamera> camera;

  // Producer (cycle thread) state.
  std::uint64_t reads = 0;
  DropCounts pending{};  // dropped since the last queued record
  bool stopped = false;

  // Shared.
  std::atomic<bool> stopping{false};
  std::atomic<std::uint64_t> written{0};
  std::atomic<std::uint64_t> dropped{0};
  std::atomic<std::uint64_t> unrecordable_frames{0};
  std::atomic<std::uint64_t> first_unrecordable_bytes{0};
  mutable std::mutex error_mutex;
  std::string error;
  std::thread writer;

  // Writer state.
  std::vector<std::uint8_t> out;
  std::uint64_t gap_total = 0;

  void set_error(std::string e) {
    const std::lock_guard lock(error_mutex);
    if (error.empty()) error = std::move(e);
  }

  // ---- producer side (cycle thread): copy, never allocate, wait only in kLossless ------------

  // A record the queue (or the frame size limit) cannot take: the next queued record carries a gap for it.
  void drop(std::uint32_t& pending_count) noexcept {
    pending_count = saturating_inc(pending_count);
    dropped.fetch_add(1, std::memory_order_relaxed);
  }

  bool acquire(bool with_frame) noexcept {
    if (records.can_write() && (!with_frame || frames.can_write())) return true;
    if (options.mode == RecordMode::kDropOnFull) return false;
    records.wait_writable();
    if (with_frame) frames.wait_writable();
    return true;
  }

  Slot& begin(RecordKind kind) noexcept {
    Slot& s = slots[records.write_slot()];
    s.kind = kind;
    s.dropped_before = pending;
    pending = {};
    return s;
  }

  /// The slot for the next record of `kind`, or nullptr when it is dropped (counted in `drop_count`).
  Slot* try_begin(RecordKind kind, std::uint32_t& drop_count, bool with_frame) noexcept {
    if (!acquire(with_frame)) {
      drop(drop_count);
      return nullptr;
    }
    return &begin(kind);
  }

  void record_sensor(bool ok, const SensorFrame& frame) noexcept {
    const std::uint64_t index = reads++;
    Slot* s = try_begin(RecordKind::kSensor, pending.sensor, false);
    if (s == nullptr) return;
    s->reads = index;
    s->ok = ok;
    s->sensor = frame;
    records.publish();
  }

  void record_ball(bool ok, const BallSighting& sighting) noexcept {
    Slot* s = try_begin(RecordKind::kBall, pending.ball, false);
    if (s == nullptr) return;
    s->reads = reads;
    s->ok = ok;
    s->ball = sighting;
    records.publish();
  }

  void record_camera(const FrameView& f) noexcept {
    const std::size_t bpp = bytes_per_pixel(f.format);
    const bool sane = f.data != nullptr && f.width > 0 && f.height > 0 && bpp > 0 && f.stride > 0 &&
                      static_cast<std::size_t>(f.stride) >= static_cast<std::size_t>(f.width) * bpp &&
                      static_cast<std::size_t>(f.width) * static_cast<std::size_t>(f.height) <= kMaxImagePixels;
    const std::size_t bytes = sane ? static_cast<std::size_t>(f.stride) * static_cast<std::size_t>(f.height) : 0;
    if (!sane || bytes > options.max_camera_frame_bytes) {
      if (unrecordable_frames.fetch_add(1, std::memory_order_relaxed) == 0) {
        first_unrecordable_bytes.store(bytes, std::memory_order_relaxed);
      }
      drop(pending.camera);
      return;
    }
    Slot* s = try_begin(RecordKind::kCamera, pending.camera, true);
    if (s == nullptr) return;
    // The pixels go first: the writer reads the frame ring only for a published camera record.
    std::memcpy(frame_slots[frames.write_slot()].data(), f.data, bytes);
    frames.publish();
    s->reads = reads;
    s->camera.reads = reads;
    s->camera.capture_time = f.capture_time;
    s->camera.sequence = f.sequence;
    s->camera.format = f.format;
    s->camera.width = static_cast<std::uint32_t>(f.width);
    s->camera.height = static_cast<std::uint32_t>(f.height);
    s->camera.stride = static_cast<std::uint32_t>(f.stride);
    records.publish();
  }

  // ---- writer thread -------------------------------------------------------------------------

  void flush() {
    if (!file.write_all(out.data(), out.size())) set_error(file.error());
    out.clear();
  }

  void encode(const Slot& s) {
    if (s.dropped_before.any()) {
      append_record(out, GapRecord{s.reads, s.dropped_before});
      gap_total += s.dropped_before.total();
    }
    switch (s.kind) {
      case RecordKind::kSensor: append_record(out, SensorRecord{s.reads, s.ok, s.sensor}); break;
      case RecordKind::kBall: append_record(out, BallRecord{s.reads, s.ok, s.ball}); break;
      case RecordKind::kCamera: append_record(out, s.camera, frame_slots[frames.read_slot()].data()); break;
      case RecordKind::kEnd: append_record(out, EndRecord{s.reads, gap_total}); break;
      case RecordKind::kGap: break;
    }
  }

  void run() {
    for (;;) {
      if (records.can_read()) {
        const Slot& s = slots[records.read_slot()];
        encode(s);
        const bool counted = s.kind != RecordKind::kEnd;
        if (s.kind == RecordKind::kCamera) frames.release();
        records.release();
        if (counted) written.fetch_add(1, std::memory_order_relaxed);
        if (out.size() >= kFlushBytes) flush();
        continue;
      }
      flush();
      if (stopping.load(std::memory_order_acquire)) {
        if (records.can_read()) continue;
        return;
      }
      std::this_thread::sleep_for(kIdleSleep);
    }
  }

  void open_and_start() {
    if (options.record_slots == 0) throw std::invalid_argument("RecordingOptions: record_slots must be at least 1");
    if (inner.camera() != nullptr) {
      if (options.camera_slots == 0) throw std::invalid_argument("RecordingOptions: camera_slots must be at least 1");
      if (options.max_camera_frame_bytes == 0 || options.max_camera_frame_bytes > kMaxLogCameraFrameBytes) {
        throw std::invalid_argument("RecordingOptions: the robot has a camera: max_camera_frame_bytes must be 1 to " +
                                    std::to_string(kMaxLogCameraFrameBytes) + ", not " +
                                    std::to_string(options.max_camera_frame_bytes));
      }
    }
    if (options.period.count() <= 0) throw std::invalid_argument("RecordingOptions: period must be positive");
    slots.resize(options.record_slots);
    if (inner.camera() != nullptr) {
      frame_slots.assign(options.camera_slots, std::vector<std::uint8_t>(options.max_camera_frame_bytes));
      camera = std::make_unique<RecCamera>(*this, *inner.camera());
    }
    if (inner.ball_sensor() != nullptr) ball = std::make_unique<RecBall>(*this, *inner.ball_sensor());
    out.reserve(kFlushBytes + kMaxSensorRecordBytes + kCameraFixedBytes + kRecordHeaderBytes +
                options.max_camera_frame_bytes + 2 * kRecordHeaderBytes + kGapPayloadBytes);

    if (std::string refused = file.create(); !refused.empty()) throw LogError(refused);
    append_header(out, LogHeader{kRobotLogVersion, options.period, options.note});
    flush();
    if (file.failed()) {
      file.close();
      throw LogError(file.error());
    }
    writer = std::thread([this] { run(); });
  }

  void stop() noexcept {
    if (stopped) return;
    stopped = true;
    // The end record (and a gap for drops not yet marked) go through the queue like any record;
    // stop is not on the cycle path, so it may wait for a slot whatever the mode.
    records.wait_writable();
    Slot& s = begin(RecordKind::kEnd);
    s.reads = reads;
    records.publish();
    stopping.store(true, std::memory_order_release);
    writer.join();
    if (!file.close()) set_error(file.error());
  }

  RecordingStatus status() const {
    RecordingStatus st;
    {
      const std::lock_guard lock(error_mutex);
      st.error = error;
    }
    const std::uint64_t unrecordable = unrecordable_frames.load(std::memory_order_relaxed);
    if (st.error.empty() && unrecordable > 0) {
      st.error = path + ": " + std::to_string(unrecordable) + " camera frame(s) not recorded: the first, of " +
                 std::to_string(first_unrecordable_bytes.load(std::memory_order_relaxed)) +
                 " bytes, is invalid or larger than max_camera_frame_bytes (" +
                 std::to_string(options.max_camera_frame_bytes) + ")";
    }
    st.records_written = written.load(std::memory_order_relaxed);
    st.dropped = dropped.load(std::memory_order_relaxed);
    return st;
  }
};

RecordingRobot::RecordingRobot(Robot& inner, const std::filesystem::path& log, RecordingOptions options)
    : impl_(std::make_unique<Impl>(inner, log, std::move(options))) {
  impl_->open_and_start();
}

RecordingRobot::~RecordingRobot() { stop(); }

std::string_view RecordingRobot::backend_name() const noexcept { return impl_->inner.backend_name(); }
Sensors& RecordingRobot::sensors() noexcept { return impl_->sensors; }
Actuators& RecordingRobot::actuators() noexcept { return impl_->inner.actuators(); }
Camera* RecordingRobot::camera() noexcept { return impl_->camera.get(); }
BallSensor* RecordingRobot::ball_sensor() noexcept { return impl_->ball.get(); }
const GroundTruth* RecordingRobot::ground_truth() const noexcept { return impl_->inner.ground_truth(); }
const BoardHealth* RecordingRobot::board_health() const noexcept { return impl_->inner.board_health(); }

RecordingStatus RecordingRobot::stop() noexcept {
  impl_->stop();
  try {
    return impl_->status();
  } catch (...) {
    return RecordingStatus{"HAL log: out of memory reporting the status", 0, 0};
  }
}

RecordingStatus RecordingRobot::status() const { return impl_->status(); }

}  // namespace ringlet::hal
