// The binary form: round trips for every type, the exact little-endian bytes, and every way a
// buffer is refused.
#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <vector>

#include "ringlet/whiteboard/binary.hpp"
#include "ringlet/whiteboard/whiteboard.hpp"
#include "wb_test_support.hpp"

namespace ringlet::wb::test {
namespace {

std::vector<std::byte> bytes(std::initializer_list<int> v) {
  std::vector<std::byte> out;
  for (const int b : v) out.push_back(static_cast<std::byte>(b));
  return out;
}

template <class T>
class WbBinaryRoundTrip : public ::testing::Test {};
TYPED_TEST_SUITE(WbBinaryRoundTrip, AllMessageTypes);

TYPED_TEST(WbBinaryRoundTrip, EveryProfileDecodesBitIdentical) {
  using T = TypeParam;
  for (int p = 0; p < kProfiles; ++p) {
    const T msg = sample<T>(p);
    const std::vector<std::byte> wire = bytes_of(msg);
    const Result<T> back = decode<T>(wire);
    ASSERT_TRUE(back.has_value()) << T::kName << " profile " << p << ": " << back.error();
    EXPECT_EQ(bytes_of(*back), wire);
    EXPECT_EQ(back->description(), msg.description());
  }
}

TYPED_TEST(WbBinaryRoundTrip, HeaderCarriesIdVersionAndSize) {
  using T = TypeParam;
  const auto wire = bytes_of(T{});
  const auto h = peek_header(wire);
  ASSERT_TRUE(h.has_value());
  EXPECT_EQ(h->id, T::kId);
  EXPECT_EQ(h->version, T::kVersion);
  EXPECT_EQ(h->payload_size, payload_size<T>());
}

TYPED_TEST(WbBinaryRoundTrip, ShortBuffersAreRefused) {
  using T = TypeParam;
  const auto wire = bytes_of(sample<T>(1));
  for (std::size_t n = 0; n < wire.size(); ++n) {
    EXPECT_FALSE(decode<T>(std::span(wire).first(n)).has_value()) << n;
  }
  std::vector<std::byte> small(wire.size() - 1);
  EXPECT_EQ(encode(T{}, small), 0U);
}

TEST(WbBinaryForm, IsLittleEndianWithAKnownLayout) {
  const auto wire = bytes_of(HeadCommand{1.0, -2.0});
  EXPECT_EQ(wire, bytes({0x02, 0x00, 0x01, 0x00, 0x10, 0x00, 0x00, 0x00,    // id 2, v1, 16 bytes
                         0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xF0, 0x3F,    // 1.0
                         0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xC0})); // -2.0

  LaserSummary l{0.0, 0.0, 0x1234};
  const auto lw = bytes_of(l);
  ASSERT_EQ(lw.size(), 8U + 18U);
  EXPECT_EQ(lw[24], std::byte{0x34});
  EXPECT_EQ(lw[25], std::byte{0x12});

  FsmControl c;
  c.machine = "ab";
  c.command = kResume;
  const auto cw = bytes_of(c);
  ASSERT_EQ(cw.size(), 8U + 2U + 32U + 1U);
  EXPECT_EQ(std::vector(cw.begin() + 8, cw.begin() + 12), bytes({0x02, 0x00, 'a', 'b'}));
  EXPECT_EQ(cw[12], std::byte{0});  // zero padded
  EXPECT_EQ(cw.back(), std::byte{1});
}

TEST(WbBinaryForm, WrongTypeIdIsRefused) {
  const auto wire = bytes_of(HeadCommand{1.0, 2.0});
  const auto r = decode<Pose>(wire);
  ASSERT_FALSE(r.has_value());
  EXPECT_EQ(r.error(), "Pose: wrong type id 2 (expected 4)");
}

TEST(WbBinaryForm, WrongVersionIsRefused) {
  auto wire = bytes_of(HeadCommand{1.0, 2.0});
  wire[2] = std::byte{2};
  const auto r = decode<HeadCommand>(wire);
  ASSERT_FALSE(r.has_value());
  EXPECT_EQ(r.error(), "HeadCommand: schema version 2 (expected 1)");
}

TEST(WbBinaryForm, WrongPayloadSizeIsRefused) {
  auto wire = bytes_of(HeadCommand{1.0, 2.0});
  wire[4] = std::byte{15};
  EXPECT_FALSE(decode<HeadCommand>(wire).has_value());
}

TEST(WbBinaryForm, InvalidFieldBytesAreRefused) {
  auto b = bytes_of(BallBelief{});
  b[8] = std::byte{2};  // visible: a bool that is neither 0 nor 1
  EXPECT_EQ(decode<BallBelief>(b).error(), "BallBelief.visible: invalid bytes");

  auto s = bytes_of(FsmControl{});
  s[8] = std::byte{33};  // machine: length 33 > capacity 32
  EXPECT_EQ(decode<FsmControl>(s).error(), "FsmControl.machine: invalid bytes");

  auto e = bytes_of(FsmControl{});
  e.back() = std::byte{7};  // command: not a schema value
  EXPECT_EQ(decode<FsmControl>(e).error(), "FsmControl.command: invalid bytes");
}

TEST(WbBinaryForm, PostBinaryRoutesByHeaderAndRefusesGarbage) {
  Whiteboard wb;
  const Pose p{1.0, 2.0, 3.0, true};
  ASSERT_TRUE(wb.post_binary(bytes_of(p)).ok());
  EXPECT_EQ(wb.get<Pose>(), p);
  EXPECT_EQ(wb.generation<Pose>(), 1U);

  auto bad = bytes_of(Pose{9.0, 9.0, 9.0, false});
  bad[2] = std::byte{9};
  EXPECT_FALSE(wb.post_binary(bad).ok());
  EXPECT_FALSE(wb.post_binary(bytes({0x63, 0x00, 0x01, 0x00, 0, 0, 0, 0})).ok());  // id 99
  EXPECT_FALSE(wb.post_binary(bytes({0x04})).ok());
  EXPECT_EQ(wb.generation<Pose>(), 1U);
  EXPECT_EQ(wb.get<Pose>(), p);
}

}  // namespace
}  // namespace ringlet::wb::test
