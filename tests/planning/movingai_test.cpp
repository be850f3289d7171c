// The MovingAI reader: good files read, bad ones refused with file:line and what was expected;
// the octile rule (no corner cutting) and the free-space assumption of MovingAiGraph.
#include <gtest/gtest.h>

#include <fstream>

#include "ringlet/planning/movingai.hpp"
#include "temp_dir.hpp"

namespace ringlet::planning {
namespace {

std::filesystem::path write(const test::TempDir& dir, const std::string& name, const std::string& text) {
  const auto p = dir / name;
  std::ofstream(p, std::ios::binary) << text;
  return p;
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const MovingAiError& e) {
    return e.what();
  }
  return "(no error)";
}

constexpr const char* kMap = "type octile\nheight 3\nwidth 4\nmap\n..@.\n.T..\nG..S\n";

TEST(MovingAi, ReadsAMapAndAScenario) {
  test::TempDir dir;
  const MovingAiMap m = read_movingai_map(write(dir, "a.map", kMap));
  EXPECT_EQ(m.width, 4);
  EXPECT_EQ(m.height, 3);
  EXPECT_TRUE(m.passable(0, 0));
  EXPECT_FALSE(m.passable(2, 0));
  EXPECT_FALSE(m.passable(1, 1));  // a tree
  EXPECT_TRUE(m.passable(0, 2));   // G
  EXPECT_TRUE(m.passable(3, 2));   // swamp
  EXPECT_FALSE(m.passable(4, 0));  // outside
  const auto ps = read_movingai_scen(write(dir, "a.scen", "version 1\n0\ta.map\t4\t3\t0\t0\t3\t2\t3.82842712\r\n\n"));
  ASSERT_EQ(ps.size(), 1U);
  EXPECT_EQ(ps[0].goal_x, 3);
  EXPECT_EQ(ps[0].line, 2);
  EXPECT_DOUBLE_EQ(ps[0].optimal, 3.82842712);
  EXPECT_EQ(check_problem(ps[0], m), "");
}

TEST(MovingAi, BadFilesNameTheFileTheLineAndWhatWasExpected) {
  test::TempDir dir;
  const auto map_error = [&](const std::string& text) {
    return error_of([&] { (void)read_movingai_map(write(dir, "bad.map", text)); });
  };
  EXPECT_NE(map_error("").find("bad.map:1: empty file"), std::string::npos);
  EXPECT_NE(map_error("type tile\n").find("bad.map:1: expected \"type octile\""), std::string::npos);
  EXPECT_NE(map_error("type octile\nheight x\n").find("bad.map:2: expected an integer height"), std::string::npos);
  EXPECT_NE(map_error("type octile\nheight 2\nwidth 0\nmap\n").find("bad.map:3: width and height must be 1 to 8192"), std::string::npos);
  EXPECT_NE(map_error("type octile\nheight 2\nwidth 2\nmap\n..\n.\n").find("bad.map:6: row 1 has 1 cells, expected 2"), std::string::npos);
  EXPECT_NE(map_error("type octile\nheight 2\nwidth 2\nmap\n..\n").find("bad.map:6: expected 2 rows"), std::string::npos);
  EXPECT_NE(map_error("type octile\nheight 1\nwidth 2\nmap\n.x\n").find("bad.map:5: column 2: unknown terrain 'x'"), std::string::npos);
  EXPECT_NE(map_error("type octile\nheight 1\nwidth 2\nmap\n..\nmore\n").find("bad.map:6: unexpected text"), std::string::npos);
  EXPECT_NE(error_of([&] { (void)read_movingai_map(dir / "missing.map"); }).find("missing.map: cannot open"), std::string::npos);

  const auto scen_error = [&](const std::string& text) {
    return error_of([&] { (void)read_movingai_scen(write(dir, "bad.scen", text)); });
  };
  EXPECT_NE(scen_error("version 2\n").find("bad.scen:1: expected \"version 1\""), std::string::npos);
  EXPECT_NE(scen_error("version 1\n0 a.map 4 3 0 0 3 2\n").find("bad.scen:2: expected 9 fields"), std::string::npos);
  EXPECT_NE(scen_error("version 1\n0 a.map 4 3 0 0 3 2 1\n0 a.map 4 3 0 zero 3 2 1\n").find("bad.scen:3: expected an integer start y"),
            std::string::npos);
  EXPECT_NE(scen_error("version 1\n0 a.map 4 3 0 0 3 2 -1\n").find("bad.scen:2: expected a non-negative optimal length"), std::string::npos);
  EXPECT_NE(scen_error("version 1\n0 a.map 4 3 0 0 3 2 nan\n").find("non-negative optimal length"), std::string::npos);
}

TEST(MovingAi, ProblemsThatDoNotFitTheirMapAreRefused) {
  test::TempDir dir;
  const MovingAiMap m = read_movingai_map(write(dir, "a.map", kMap));
  MovingAiProblem p;
  p.map_width = 4;
  p.map_height = 3;
  p.goal_x = 3;
  EXPECT_EQ(check_problem(p, m), "");
  p.goal_x = 2;  // '@'
  EXPECT_NE(check_problem(p, m).find("the goal (2, 0) is not a passable cell"), std::string::npos);
  p.goal_x = 3;
  p.start_x = -1;
  EXPECT_NE(check_problem(p, m).find("the start (-1, 0)"), std::string::npos);
  p.start_x = 0;
  p.map_width = 5;
  EXPECT_NE(check_problem(p, m).find("5 × 3 map, the map is 4 × 3"), std::string::npos);
}

TEST(MovingAi, OctileStepsNeverCutACornerAndTheUnknownIsFree) {
  test::TempDir dir;
  const MovingAiMap m = read_movingai_map(write(dir, "a.map", kMap));
  MovingAiGraph known(m, true);
  const Cost cell = MovingAiGraph::kCellCost;
  EXPECT_EQ(known.step_cost(known.vertex(0, 0), 0), cell);                          // (0,0) → (1,0)
  EXPECT_EQ(known.step_cost(known.vertex(0, 0), 1), kInfiniteCost);                 // → (1,1): a tree
  EXPECT_EQ(known.step_cost(known.vertex(1, 0), 1), kInfiniteCost);                 // → (2,1) past '@' at (2,0)
  EXPECT_EQ(known.step_cost(known.vertex(2, 1), 1), MovingAiGraph::kDiagonalCost);  // → (3,2): both sides free
  EXPECT_EQ(known.step_cost(known.vertex(3, 2), 0), kInfiniteCost);                 // off the map
  EXPECT_GE(MovingAiGraph::kDiagonalCost, known.min_diagonal_cost());
  MovingAiGraph unknown(m, false);
  EXPECT_EQ(unknown.step_cost(unknown.vertex(0, 0), 1), MovingAiGraph::kDiagonalCost);  // the tree is not known yet
  EXPECT_FALSE(unknown.reveal(unknown.vertex(0, 0)));  // free
  EXPECT_TRUE(unknown.reveal(unknown.vertex(1, 1)));   // the tree: the planner must hear of it
  EXPECT_FALSE(unknown.reveal(unknown.vertex(1, 1)));  // only once
  EXPECT_EQ(unknown.step_cost(unknown.vertex(0, 0), 1), kInfiniteCost);
}

}  // namespace
}  // namespace ringlet::planning
