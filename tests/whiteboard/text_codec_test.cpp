// The text form: exact round trips for every type, the readable layout, errors that name the
// field, and a by-name post that changes nothing on bad text.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "ringlet/whiteboard/whiteboard.hpp"
#include "wb_test_support.hpp"

namespace ringlet::wb::test {
namespace {

template <class T>
class WbTextRoundTrip : public ::testing::Test {};
TYPED_TEST_SUITE(WbTextRoundTrip, AllMessageTypes);

TYPED_TEST(WbTextRoundTrip, EveryProfileReadsBackBitIdentical) {
  using T = TypeParam;
  for (int p = 0; p < kProfiles; ++p) {
    const T msg = sample<T>(p);
    const std::string text = msg.description();
    const Result<T> back = T::from_string(text);
    ASSERT_TRUE(back.has_value()) << T::kName << " profile " << p << ": " << back.error()
                                  << "\n  text: " << text;
    EXPECT_EQ(bytes_of(*back), bytes_of(msg)) << T::kName << " profile " << p << ": " << text;
    EXPECT_EQ(back->description(), text);
  }
}

TYPED_TEST(WbTextRoundTrip, DefaultReadsBack) {
  using T = TypeParam;
  const Result<T> back = T::from_string(T{}.description());
  ASSERT_TRUE(back.has_value()) << back.error();
  EXPECT_EQ(*back, T{});
}

TEST(WbTextForm, IsReadableCommaSeparated) {
  BallBelief b;
  b.visible = true;
  b.x = 1.5;
  b.y = -0.25;
  b.confidence = 0.1;
  b.simulated = false;
  EXPECT_EQ(b.description(), "true,1.5,-0.25,0.1,false");

  FsmControl c;
  c.machine = "head";
  c.command = kRestart;
  EXPECT_EQ(c.description(), "head,restart");

  LaserSummary l{std::numeric_limits<double>::infinity(), -0.0, 65535};
  EXPECT_EQ(l.description(), "inf,-0,65535");
}

TEST(WbTextForm, DoublesUseTheShortestExactForm) {
  HeadCommand h{0.1 + 0.2, 1e-320};
  EXPECT_EQ(h.description(), "0.30000000000000004,1e-320");
  const auto back = HeadCommand::from_string(h.description());
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(back->yaw, 0.1 + 0.2);
  EXPECT_EQ(back->pitch, 1e-320);
}

TEST(WbTextForm, NanInfAndNegativeZeroReadBack) {
  const auto p = Pose::from_string("nan,-inf,-0,1");
  ASSERT_TRUE(p.has_value()) << p.error();
  EXPECT_TRUE(std::isnan(p->x));
  EXPECT_EQ(p->y, -std::numeric_limits<double>::infinity());
  EXPECT_TRUE(std::signbit(p->theta));
  EXPECT_TRUE(p->valid);
}

TEST(WbTextForm, StringsEscapeCommasBackslashesAndControls) {
  Print pr;
  pr.text = std::string_view("a,b\\c\nd\x01", 8);
  EXPECT_EQ(pr.description(), "a\\,b\\\\c\\nd\\x01");
  const auto back = Print::from_string(pr.description());
  ASSERT_TRUE(back.has_value()) << back.error();
  EXPECT_EQ(back->text, pr.text);
}

TEST(WbTextForm, ToleratesSpacesAroundNumbersAndALeadingPlus) {
  const auto m = MotionCommand::from_string(" +0.5 , -1 ,  true ");
  ASSERT_TRUE(m.has_value()) << m.error();
  EXPECT_EQ(m->curvature, 0.5);
  EXPECT_EQ(m->velocity, -1.0);
  EXPECT_TRUE(m->stop);
}

TEST(WbTextForm, ArraysAreTheirElements) {
  ExecutiveTiming t;
  t.frames = 10;
  t.task_count = 2;
  t.task_worst_ns[0] = 150;
  t.task_worst_ns[1] = -1;
  t.task_every[0] = 5;
  // frames, overruns, slips, task_count, 16 worst times, the (empty) names, then 16 of each array.
  std::string want = "10,0,0,2,150,-1";
  for (int i = 0; i < 14; ++i) want += ",0";
  want += ",";  // task_names: empty
  want += ",5";
  for (int i = 0; i < 15 + 4 * 16; ++i) want += ",0";
  EXPECT_EQ(t.description(), want);
}

// ---- errors -------------------------------------------------------------------------------------

TEST(WbTextErrors, NameTheFieldAndQuoteTheToken) {
  const auto r = BallBelief::from_string("true,abc,0,0,false");
  ASSERT_FALSE(r.has_value());
  EXPECT_EQ(r.error(), "BallBelief.x: not a number: \"abc\"");
}

TEST(WbTextErrors, EachKind) {
  EXPECT_EQ(BallBelief::from_string("yes,0,0,0,false").error(),
            "BallBelief.visible: not a bool (true/false/1/0): \"yes\"");
  EXPECT_EQ(BallBelief::from_string("true,1,2").error(), "BallBelief.confidence: missing");
  EXPECT_EQ(HeadCommand::from_string("1,2,3").error(), "HeadCommand: too many fields (expected 2)");
  EXPECT_EQ(HeadCommand::from_string("1,1e999").error(), "HeadCommand.pitch: out of range: \"1e999\"");
  EXPECT_EQ(HeadCommand::from_string("1,").error(), "HeadCommand.pitch: not a number: \"\"");
  EXPECT_EQ(LaserSummary::from_string("1,2,65536").error(),
            "LaserSummary.valid_beams: out of range: \"65536\"");
  EXPECT_EQ(LaserSummary::from_string("1,2,-1").error(),
            "LaserSummary.valid_beams: not a number: \"-1\"");
  EXPECT_EQ(FsmControl::from_string("m,explode").error(),
            "FsmControl.command: unknown value: \"explode\"");
  EXPECT_EQ(FsmControl::from_string("m\\q,resume").error(), "FsmControl.machine: bad escape: \"m\\q\"");
  EXPECT_EQ(FsmControl::from_string(std::string(33, 'm') + ",resume").error(),
            "FsmControl.machine: too long: \"" + std::string(33, 'm') + "\"");
  EXPECT_EQ(ExecutiveTiming::from_string("1,2,3,4,5,6,x").error(),
            "ExecutiveTiming.task_worst_ns[2]: not a number: \"x\"");
}

TEST(WbTextErrors, BadTextLeavesTheBoardUnchanged) {
  Whiteboard wb;
  wb.post(BallBelief{true, 1.0, 2.0, 0.5, false});
  const Status s = wb.post_text("BallBelief", "true,abc,0,0,false");
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error(), "BallBelief.x: not a number: \"abc\"");
  EXPECT_EQ(wb.generation<BallBelief>(), 1U);
  EXPECT_EQ(wb.get<BallBelief>(), (BallBelief{true, 1.0, 2.0, 0.5, false}));

  EXPECT_FALSE(wb.post_text("NoSuchType", "1").ok());
  ASSERT_TRUE(wb.post_text("BallBelief", "false,3,4,0.25,true").ok());
  EXPECT_EQ(wb.generation<BallBelief>(), 2U);
  EXPECT_EQ(wb.get<BallBelief>(), (BallBelief{false, 3.0, 4.0, 0.25, true}));
  EXPECT_EQ(*wb.describe_newest("BallBelief"), "false,3,4,0.25,true");
}

}  // namespace
}  // namespace ringlet::wb::test
