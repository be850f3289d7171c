// The whiteboard log: every message dispatched is logged with its frame and generation, identical
// runs give identical logs, the first difference is named with both messages' text, and a damaged
// log is refused naming what and where.
#include "ringlet/whiteboard/message_log.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include "ringlet/whiteboard/whiteboard.hpp"
#include "temp_dir.hpp"

namespace {

using namespace ringlet::wb;
namespace fs = std::filesystem;

// One folder per test process, removed when it exits.
fs::path dir() {
  static const ringlet::test::TempDir d("ringlet_wb_log");
  return d.path();
}

std::vector<char> bytes_of(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// A small run: per frame a BallBelief, a HeadCommand every other frame, and a burst of three
/// Poses in frame 4; `twist` changes one value (BallBelief.x at frame `twist`).
void run(const fs::path& path, int frames, int twist = -1, MessageLogOptions options = {}) {
  Whiteboard wb(8);
  MessageLogger logger(wb, path, options);
  for (int f = 0; f < frames; ++f) {
    logger.set_frame(static_cast<std::uint64_t>(f));
    BallBelief b;
    b.visible = f % 3 != 0;
    b.x = 1.0 + 0.5 * f + (f == twist ? 1e-9 : 0.0);
    b.y = -0.25;
    wb.post(b);
    if (f % 2 == 0) wb.post(HeadCommand{0.1 * f, -0.2});
    if (f == 4) {
      for (int k = 0; k < 3; ++k) {
        Pose p;
        p.x = k;
        wb.post(p);
      }
    }
    wb.dispatch();
  }
  const MessageLogStatus st = logger.stop();
  EXPECT_TRUE(st.ok()) << st.error;
}

TEST(MessageLog, LogsEveryDispatchedMessageWithItsFrameAndGeneration) {
  const auto path = dir() / "run.wblog";
  run(path, 6);
  const Result<MessageLog> log = read_message_log(path);
  ASSERT_TRUE(log) << log.error();
  EXPECT_TRUE(log->complete);
  EXPECT_EQ(log->dropped, 0u);
  ASSERT_EQ(log->messages.size(), 6u + 3u + 3u);
  // Frame 0: types in id order (BallBelief 1, HeadCommand 2).
  EXPECT_EQ(log->messages[0].describe(), "BallBelief generation 1 (frame 0): false,1,-0.25,0,false");
  EXPECT_EQ(log->messages[1].describe(), "HeadCommand generation 1 (frame 0): 0,-0.2");
  // Frame 4: the three Poses, oldest first, after BallBelief and HeadCommand.
  std::vector<std::uint64_t> pose_generations;
  for (const auto& m : log->messages) {
    if (m.type == Pose::kId) {
      EXPECT_EQ(m.frame, 4u);
      pose_generations.push_back(m.generation);
    }
  }
  EXPECT_EQ(pose_generations, (std::vector<std::uint64_t>{1, 2, 3}));
  EXPECT_EQ(log->messages.back().frame, 5u);
}

TEST(MessageLog, IdenticalRunsGiveIdenticalLogs) {
  const auto a = dir() / "a.wblog";
  const auto b = dir() / "b.wblog";
  run(a, 50);
  run(b, 50);
  EXPECT_EQ(bytes_of(a), bytes_of(b));
  const auto la = read_message_log(a);
  const auto lb = read_message_log(b);
  ASSERT_TRUE(la && lb);
  EXPECT_EQ(first_difference(*la, *lb), std::nullopt);
}

TEST(MessageLog, TheFirstDifferenceIsNamedWithBothTexts) {
  const auto a = dir() / "base.wblog";
  const auto b = dir() / "twisted.wblog";
  run(a, 20);
  run(b, 20, 7);
  const auto la = read_message_log(a);
  const auto lb = read_message_log(b);
  ASSERT_TRUE(la && lb);
  const auto diff = first_difference(*la, *lb);
  ASSERT_TRUE(diff.has_value());
  EXPECT_EQ(*diff,
            "message 14: expected BallBelief generation 8 (frame 7): true,4.5,-0.25,0,false; got BallBelief "
            "generation 8 (frame 7): true,4.500000001,-0.25,0,false");

  const auto c = dir() / "shorter.wblog";
  run(c, 19);
  const auto lc = read_message_log(c);
  ASSERT_TRUE(lc);
  EXPECT_EQ(*first_difference(*la, *lc),
            "expected 33 messages, got 32; the first missing is BallBelief generation 20 (frame 19): "
            "true,10.5,-0.25,0,false");
  EXPECT_NE(first_difference(*lc, *la)->find("the first extra is BallBelief generation 20"), std::string::npos);
}

TEST(MessageLog, SubscriptionsAreStartUpOnly) {
  Whiteboard wb;
  wb.dispatch();
  EXPECT_THROW(MessageLogger(wb, dir() / "late.wblog"), std::logic_error);
  EXPECT_FALSE(fs::exists(dir() / "late.wblog"));
}

TEST(MessageLog, DropOnFullCountsDropsAndSuchALogNeverCompares) {
  const auto path = dir() / "drops.wblog";
  MessageLogOptions o;
  o.mode = MessageLogMode::kDropOnFull;
  o.slots = 1;
  {
    Whiteboard wb(64);
    MessageLogger logger(wb, path, o);
    for (int i = 0; i < 40; ++i) wb.post(HeadCommand{0.01 * i, 0.0});
    wb.dispatch();  // 40 messages into one slot in one go: the writer cannot keep up
    const MessageLogStatus st = logger.stop();
    EXPECT_TRUE(st.ok()) << st.error;
    EXPECT_GT(st.dropped, 0u);
    EXPECT_EQ(st.logged + st.dropped, 40u);
  }
  const auto log = read_message_log(path);
  ASSERT_TRUE(log) << log.error();
  EXPECT_GT(log->dropped, 0u);
  EXPECT_EQ(log->messages.size() + log->dropped, 40u);
  EXPECT_NE(first_difference(*log, *log)->find("dropped"), std::string::npos);
}

TEST(MessageLog, DamagedLogsAreRefusedAndCutLogsNeverCrash) {
  const auto path = dir() / "good.wblog";
  run(path, 5);
  const auto raw = bytes_of(path);
  const auto parse = [](std::vector<char> b) {
    return parse_message_log(std::as_bytes(std::span<const char>(b.data(), b.size())), "log");
  };
  auto bad = raw;
  bad[0] = 'X';
  EXPECT_EQ(parse(bad).error(), "log: wrong magic (not a Ringlet whiteboard log) at byte 0");
  bad = raw;
  bad[8] = 2;
  EXPECT_EQ(parse(bad).error(), "log: unsupported version 2 (this build reads version 1) at byte 8");
  bad = raw;
  bad[16 + 2] = 9;  // BallBelief's schema version
  EXPECT_NE(parse(bad).error().find("the log's schema differs from this build's: type 0 is id 1 version 9"),
            std::string::npos);
  const std::size_t first_record = 16 + kTypeCount * 8;
  bad = raw;
  bad[first_record] = 7;
  EXPECT_EQ(parse(bad).error(), "log: unknown record kind 7 at byte " + std::to_string(first_record));
  bad = raw;
  bad[first_record + 1 + 24 + 8] = 2;  // BallBelief.visible: not a bool
  EXPECT_NE(parse(bad).error().find("BallBelief"), std::string::npos) << parse(bad).error();
  bad = raw;
  bad.push_back(1);
  EXPECT_NE(parse(bad).error().find("data after the end record"), std::string::npos);

  std::size_t shorter = 0;
  for (std::size_t n = 0; n < raw.size(); ++n) {
    const auto r = parse(std::vector<char>(raw.begin(), raw.begin() + static_cast<std::ptrdiff_t>(n)));
    if (r) {
      EXPECT_FALSE(r->complete);
      ++shorter;
    } else {
      EXPECT_EQ(r.error().rfind("log: ", 0), 0u);
      EXPECT_NE(r.error().find(" at byte "), std::string::npos) << r.error();
    }
  }
  EXPECT_EQ(shorter, 1u + 5u + 3u + 3u);  // cut after the header or after a message record
  EXPECT_FALSE(read_message_log(dir()));   // a directory
}

}  // namespace
