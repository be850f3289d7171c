// The board's CAN protocol table and codec (hal/can/protocol.hpp): the table is well-formed, every
// frame round-trips at its range's ends and inside, bad frames are refused by kind, and the DBC
// file and README table committed in hal/can/ are the ones the table writes.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include "ringlet/hal/can/protocol.hpp"

namespace ringlet::hal::can {
namespace {

Values values_at(const FrameSpec& f, double t) {  // t in [0, 1] along every signal's range
  Values v;
  for (std::size_t i = 0; i < f.signals.size(); ++i) {
    v.v[i] = f.signals[i].min + t * (f.signals[i].max - f.signals[i].min);
    v.present[i] = true;
  }
  return v;
}

TEST(CanProtocol, TheTableIsWellFormed) {
  std::set<std::uint32_t> ids;
  std::uint32_t last = 0;
  for (const FrameSpec& f : frames()) {
    EXPECT_LT(f.id, 0x800U) << f.name << ": an 11-bit ID";
    EXPECT_GT(f.id, last) << f.name << ": frames in ID order";
    last = f.id;
    EXPECT_TRUE(ids.insert(f.id).second);
    EXPECT_GE(f.length, 1);
    EXPECT_LE(f.length, 8) << f.name << ": classic CAN";
    EXPECT_LE(f.signals.size(), 8U);
    std::array<bool, 8> used{};
    for (const Signal& s : f.signals) {
      ASSERT_LE(s.offset + s.bytes, f.length) << f.name << "." << s.name << " ends past the frame";
      for (int b = s.offset; b < s.offset + s.bytes; ++b) {
        EXPECT_FALSE(used[static_cast<std::size_t>(b)]) << f.name << "." << s.name << " overlaps at byte " << b;
        used[static_cast<std::size_t>(b)] = true;
      }
      EXPECT_LT(s.min, s.max) << f.name << "." << s.name;
      const double span = std::ldexp(1.0, 8 * s.bytes - (s.is_signed ? 1 : 0));
      EXPECT_LE(s.max / s.scale, span) << f.name << "." << s.name << ": the range does not fit the width";
      if (s.no_value) {
        const double raw = static_cast<double>(*s.no_value);
        EXPECT_TRUE(raw < s.min / s.scale - 0.5 || raw > s.max / s.scale + 0.5) << f.name << "." << s.name << ": the sentinel is a valid value";
      }
    }
    EXPECT_EQ(find_frame(f.id), &f);
  }
  EXPECT_EQ(find_frame(0x7FF), nullptr);
}

TEST(CanProtocol, EveryFrameRoundTripsAcrossItsRanges) {
  for (const FrameSpec& f : frames()) {
    for (const double t : {0.0, 0.013, 0.5, 0.77, 1.0}) {
      const Values in = values_at(f, t);
      RawFrame raw;
      ASSERT_TRUE(encode(f, in, raw).ok()) << f.name << " at " << t;
      EXPECT_EQ(raw.id, f.id);
      EXPECT_EQ(raw.length, f.length);
      const FrameSpec* spec = nullptr;
      Values out;
      const CodecResult r = decode(raw, spec, out);
      ASSERT_TRUE(r.ok()) << describe(raw, r);
      EXPECT_EQ(spec, &f);
      for (std::size_t i = 0; i < f.signals.size(); ++i) {
        EXPECT_TRUE(out.present[i]);
        // Half a step inside the range; a full step at an end that is not a multiple of it (pi).
        EXPECT_NEAR(out[i], in[i], (t == 0.0 || t == 1.0 ? 1.0 : 0.5) * f.signals[i].scale + 1e-12) << f.name << "." << f.signals[i].name << " at " << t;
      }
    }
  }
}

TEST(CanProtocol, SignalsAreLittleEndianAtTheirOffsets) {
  Values v;
  v.v = {0.5, -1.0, 7, 1};  // curvature 500, velocity -1000, counter 7, enable 1
  v.present = {true, true, true, true};
  RawFrame raw;
  ASSERT_TRUE(encode(*find_frame(kDriveId), v, raw).ok());
  const std::array<std::uint8_t, 6> want{0xF4, 0x01, 0x18, 0xFC, 0x07, 0x01};
  for (std::size_t i = 0; i < want.size(); ++i) EXPECT_EQ(raw.data[i], want[i]) << "byte " << i;
}

TEST(CanProtocol, NoValueSentinelsDecodeAsAbsent) {
  Values v = values_at(*find_frame(kPoseId), 0.5);
  v.present[0] = v.present[1] = false;  // no fix
  RawFrame raw;
  ASSERT_TRUE(encode(*find_frame(kPoseId), v, raw).ok());
  EXPECT_EQ(raw.data[0], 0x00);
  EXPECT_EQ(raw.data[2], 0x80);  // -8388608 as i24
  const FrameSpec* spec = nullptr;
  Values out;
  ASSERT_TRUE(decode(raw, spec, out).ok());
  EXPECT_FALSE(out.present[0]);
  EXPECT_FALSE(out.present[1]);
  EXPECT_TRUE(out.present[2]);
  // A laser beam that saw nothing is raw 0.
  RawFrame ranges{kLaserRangesId, 8, {3, 17, 0, 0, 0xE8, 0x03, 0, 0}};
  ASSERT_TRUE(decode(ranges, spec, out).ok());
  EXPECT_FALSE(out.present[2]);
  EXPECT_DOUBLE_EQ(out[3], 1.0);
  EXPECT_FALSE(out.present[4]);
}

TEST(CanProtocol, BadFramesAreRefusedByKind) {
  const FrameSpec* spec = nullptr;
  Values out;
  const RawFrame unknown{0x7FF, 8, {}};
  EXPECT_EQ(decode(unknown, spec, out).error, CodecError::kUnknownId);
  EXPECT_EQ(describe(unknown, decode(unknown, spec, out)), "ID 0x7FF: not a frame of the protocol");
  const RawFrame short_drive{kDriveId, 5, {}};
  EXPECT_EQ(decode(short_drive, spec, out).error, CodecError::kWrongLength);
  EXPECT_EQ(describe(short_drive, decode(short_drive, spec, out)), "CTRL_DRIVE (0x100): 5 data bytes, the protocol says 6");
  const RawFrame fast{kOdometryId, 8, {0, 0, 0, 0, 0x70, 0x17, 0, 0}};  // velocity 6.0 m/s > 5
  const CodecResult r = decode(fast, spec, out);
  EXPECT_EQ(r.error, CodecError::kOutOfRange);
  EXPECT_EQ(describe(fast, r), "BOARD_ODOMETRY.velocity: value out of range");
  const RawFrame bad_enable{kDriveId, 6, {0, 0, 0, 0, 0, 2}};
  EXPECT_EQ(decode(bad_enable, spec, out).error, CodecError::kOutOfRange);
}

TEST(CanProtocol, EncodeRefusesWhatTheBoardCouldNotTakeAndLeavesTheFrameAlone) {
  const FrameSpec& drive = *find_frame(kDriveId);
  RawFrame raw{0x123, 3, {9, 9, 9}};
  const RawFrame before = raw;
  Values v = values_at(drive, 0.5);
  v.v[1] = 5.2;  // m/s
  EXPECT_EQ(encode(drive, v, raw).error, CodecError::kOutOfRange);
  EXPECT_EQ(encode(drive, v, raw).signal, 1);
  v.v[1] = std::nan("");
  EXPECT_EQ(encode(drive, v, raw).error, CodecError::kNotFinite);
  v = values_at(drive, 0.5);
  v.present[0] = false;  // curvature has no "no value"
  EXPECT_EQ(encode(drive, v, raw).error, CodecError::kOutOfRange);
  EXPECT_EQ(raw.id, before.id);
  EXPECT_EQ(raw.length, before.length);
  EXPECT_EQ(raw.data, before.data);
}

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(CanProtocol, TheCommittedDbcAndReadmeTableAreTheTables) {
  EXPECT_EQ(read_text(RINGLET_CAN_DIR "/ringlet_board.dbc"), dbc_text())
      << "hal/can/ringlet_board.dbc is stale: build/<preset>/hal/can/ringlet-can-spec --dbc > hal/can/ringlet_board.dbc";
  const std::string readme = read_text(RINGLET_CAN_DIR "/README.md");
  const auto begin = readme.find("<!--can-frames-->\n");
  const auto end = readme.find("<!--/can-frames-->");
  ASSERT_NE(begin, std::string::npos) << "hal/can/README.md has no <!--can-frames--> block";
  ASSERT_NE(end, std::string::npos);
  EXPECT_EQ(readme.substr(begin + 18, end - begin - 18), markdown_table())
      << "hal/can/README.md's frame table is stale: paste `ringlet-can-spec --markdown` between the markers";
}

}  // namespace
}  // namespace ringlet::hal::can
