// The world file format: a good file in full, and every way a file can be wrong, each with the
// exact "<source>:<line>: " position and the phrase that tells the author what to fix.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <optional>
#include <ostream>
#include <string>

#include "ringlet/sim_hal/world.hpp"

namespace ringlet::sim_hal {
namespace {

const std::string kTestWorlds = RINGLET_TEST_WORLDS_DIR;

TEST(SimWorldParser, ReadsEveryStatement) {
  const World world = load_world(kTestWorlds + "/small.world");
  EXPECT_EQ(world.name, "Small # yard");
  EXPECT_EQ(world.min.x, -5.0);
  EXPECT_EQ(world.min.y, -2.5);
  EXPECT_EQ(world.max.x, 5.0);
  EXPECT_EQ(world.max.y, 7.5);
  EXPECT_EQ(world.start.x, 0.0);
  EXPECT_EQ(world.start.y, 0.0);
  EXPECT_DOUBLE_EQ(world.start.theta, std::numbers::pi / 2.0);

  ASSERT_EQ(world.circles.size(), 2U);
  EXPECT_EQ(world.circles[1].centre.x, -3.0);
  EXPECT_EQ(world.circles[1].radius, 1.0);
  ASSERT_EQ(world.polygons.size(), 2U);
  EXPECT_EQ(world.polygons[0].vertices.size(), 3U);
  EXPECT_EQ(world.polygons[1].vertices.size(), 4U);
  EXPECT_EQ(world.polygons[0].vertices[2].y, 6.5);

  ASSERT_EQ(world.markings.size(), 2U);
  EXPECT_EQ(world.markings[0].width, 0.05);  // the default
  EXPECT_EQ(world.markings[1].width, 0.1);

  ASSERT_TRUE(world.ball.has_value());
  EXPECT_EQ(world.ball->position.x, 1.5);
  EXPECT_EQ(world.ball->radius, 0.05);  // the default
}

// Header, bounds and start are all a world needs: goals are the mission's (firmware configuration).
TEST(SimWorldParser, MinimalWorldHasNoOptionalParts) {
  const World world = parse_world("ringlet-world 1\nbounds 0 0 10 10\nstart 1 1 0", "min.world");
  EXPECT_TRUE(world.name.empty());
  EXPECT_TRUE(world.circles.empty());
  EXPECT_TRUE(world.polygons.empty());
  EXPECT_TRUE(world.markings.empty());
  EXPECT_FALSE(world.ball.has_value());
  EXPECT_TRUE(world.rings.empty());
  EXPECT_EQ(world.start_line, 3);
}

TEST(SimWorldParser, AcceptsWindowsLineEndingsAndTabs) {
  const World world = parse_world("ringlet-world 1\r\nbounds\t0 0 10 10\r\nstart 1 1 -90\r\n", "crlf.world");
  EXPECT_EQ(world.max.y, 10.0);
  EXPECT_DOUBLE_EQ(world.start.theta, -std::numbers::pi / 2.0);
}

TEST(SimWorldParser, WrapsTheStartHeading) {
  const World world = parse_world("ringlet-world 1\nbounds 0 0 10 10\nstart 1 1 270\n", "w");
  EXPECT_DOUBLE_EQ(world.start.theta, -std::numbers::pi / 2.0);
}

// Found by the world fuzz target: 1e308 degrees is finite but overflowed to infinity in
// radians, and the heading became NaN.
TEST(SimWorldParser, HugeFiniteAnglesStayFinite) {
  const World world = parse_world(
      "ringlet-world 2\nbounds 0 0 10 10\nstart 1 1 1e308\nlighting 1 0.1 0.3 2 -1e308\n", "w");
  EXPECT_TRUE(std::isfinite(world.start.theta));
  EXPECT_LE(std::abs(world.start.theta), std::numbers::pi);
  EXPECT_TRUE(std::isfinite(world.lighting.sun_angle));
  EXPECT_LE(std::abs(world.lighting.sun_angle), std::numbers::pi);
}

// ---------------------------------------------------------------------------------------------

// The message of the WorldError that LOAD throws; none when it returns a world. Nothing half-loaded:
// the only way out of the parser is a complete World or this exception.
std::optional<std::string> world_error(const std::function<World()>& load) {
  try {
    (void)load();
  } catch (const WorldError& e) {
    return e.what();
  }
  return std::nullopt;
}

struct BadWorld {
  const char* name;
  std::string text;
  std::string position;  // the exact "<source>:<line>: " the message must start with
  std::string phrase;    // and a phrase it must contain
};

// Lines 1-4 of a valid world; most cases append their bad line as line 5.
const std::string kHead = "ringlet-world 1\nbounds 0 0 10 10\nstart 1 1 0\n# line 4\n";
const std::string kHead2 = "ringlet-world 2\nbounds 0 0 10 10\nstart 1 1 0\n# line 4\n";
// Lines 1-4 of a world still missing its start, for the cases whose bad line is the start.
const std::string kHeadNoStart = "ringlet-world 1\nbounds 0 0 10 10\n# no start yet\n# line 4\n";

const BadWorld kBadWorlds[] = {
    {"unknown_keyword", kHead + "cirle 1 2 3\n", "t.world:5: ", "unknown keyword 'cirle'"},
    {"quoted_keyword", kHead + "\"circle\" 1 2 3\n", "t.world:5: ", "unknown keyword \"circle\""},
    {"too_few_arguments", kHeadNoStart + "start 1\n", "t.world:5: ",
     "start: expected 3 arguments (x y heading_deg), got 1"},
    {"circle_too_few", kHead + "circle 1 2\n", "t.world:5: ",
     "circle: expected 3 to 5 arguments (x y radius [height [kind]]), got 2"},
    {"too_many_arguments", kHeadNoStart + "start 1 2 3 4\n", "t.world:5: ",
     "start: expected 3 arguments (x y heading_deg), got 4"},
    {"ball_too_many", kHead + "ball 1 2 0.1 4\n", "t.world:5: ", "ball: expected 2 or 3 arguments (x y [radius]), got 4"},
    {"optional_argument_count", kHead + "marking 1 1 2\n", "t.world:5: ",
     "marking: expected 4 or 5 arguments (x1 y1 x2 y2 [width]), got 3"},
    {"trailing_junk", kHead + "circle 1 2 1.5m\n", "t.world:5: ", "circle: radius is not a number: '1.5m'"},
    {"word_for_number", kHead + "ball five 5\n", "t.world:5: ", "ball: x is not a number: 'five'"},
    {"quoted_number", kHead + "ball \"5\" 5\n", "t.world:5: ", "ball: x is not a number: '\"5\"'"},
    {"double_sign", kHead + "ball +-5 5\n", "t.world:5: ", "ball: x is not a number: '+-5'"},
    {"infinite", kHead + "circle 1 2 inf\n", "t.world:5: ", "circle: radius must be finite, got 'inf'"},
    {"not_a_number", kHead + "ball nan 2\n", "t.world:5: ", "ball: x must be finite, got 'nan'"},
    {"out_of_range", kHead + "circle 1 1e999 1\n", "t.world:5: ", "circle: y is out of range: '1e999'"},
    {"negative_radius", kHead + "circle 5 7 -1\n", "t.world:5: ", "circle: radius must be > 0, got -1"},
    {"zero_radius", kHead + "circle 5 7 0\n", "t.world:5: ", "circle: radius must be > 0, got 0"},
    {"ball_radius", kHead + "ball 5 7 -0.1\n", "t.world:5: ", "ball: radius must be > 0, got -0.1"},
    {"marking_width", kHead + "marking 1 1 2 2 0\n", "t.world:5: ", "marking: width must be > 0, got 0"},
    {"marking_no_length", kHead + "marking 1 1 1 1\n", "t.world:5: ", "marking: the two end points are the same"},
    {"bounds_x_reversed", "ringlet-world 1\nbounds 5 0 3 10\nstart 1 1 0\n", "t.world:2: ",
     "bounds: xmin (5) must be < xmax (3)"},
    {"bounds_y_empty", "ringlet-world 1\nbounds 0 2 10 2\nstart 1 1 0\n", "t.world:2: ",
     "bounds: ymin (2) must be < ymax (2)"},
    {"bounds_arguments", "ringlet-world 1\nbounds 0 0 10\n", "t.world:2: ",
     "bounds: expected 4 arguments (xmin ymin xmax ymax), got 3"},
    {"duplicate_bounds", kHead + "bounds 0 0 10 10\n", "t.world:5: ", "bounds: given twice (first on line 2)"},
    {"duplicate_start", kHead + "start 2 2 0\n", "t.world:5: ", "start: given twice (first on line 3)"},
    {"duplicate_ball", kHead + "ball 1 1\n# comment\nball 2 2\n", "t.world:7: ", "ball: given twice (first on line 5)"},
    {"duplicate_name", kHead + "name \"a\"\nname \"b\"\n", "t.world:6: ", "name: given twice (first on line 5)"},
    {"duplicate_header", kHead + "ringlet-world 1\n", "t.world:5: ", "ringlet-world: given twice (first on line 1)"},
    {"name_not_quoted", kHead + "name Courtyard\n", "t.world:5: ", "name: expected one quoted string"},
    {"name_two_strings", kHead + "name \"a\" \"b\"\n", "t.world:5: ", "name: expected one quoted string"},
    {"unterminated_string", kHead + "name \"Court\n", "t.world:5: ", "unterminated quoted string"},
    {"text_after_string", kHead + "name \"Court\"yard\n", "t.world:5: ", "unexpected text right after a quoted string"},
    {"missing_header", "bounds 0 0 10 10\nstart 1 1 0\n", "t.world:1: ",
     "missing header: the first line must be 'ringlet-world 2', got 'bounds'"},
    {"missing_header_after_comments", "# a world\n\n   \nbounds 0 0 10 10\n", "t.world:4: ", "missing header"},
    {"empty_file", "", "t.world:1: ", "end of file: missing header 'ringlet-world 2'"},
    {"only_comments", "# nothing\n# here\n", "t.world:2: ", "end of file: missing header"},
    {"unsupported_version", "ringlet-world 3\nbounds 0 0 10 10\n", "t.world:1: ",
     "ringlet-world: unsupported version 3 (this build reads versions 1 to 2)"},
    {"version_zero", "ringlet-world 0\n", "t.world:1: ", "ringlet-world: unsupported version 0"},
    // Format version 2 statements: refused in a version 1 file, checked in a version 2 file.
    {"ring_in_version_1", kHead + "ring 5 5 1\n", "t.world:5: ",
     "ring: this statement needs format version 2 (the header on line 1 says 1)"},
    {"lighting_in_version_1", kHead + "lighting 1 0.1 0.2 2 30\n", "t.world:5: ",
     "lighting: this statement needs format version 2"},
    {"circle_height_in_version_1", kHead + "circle 5 5 0.2 0.58\n", "t.world:5: ",
     "circle: height and kind needs format version 2"},
    {"circle_bad_kind", kHead2 + "circle 5 5 0.2 0.58 tree\n", "t.world:5: ",
     "circle: kind must be robot, post or obstacle, got 'tree'"},
    {"circle_quoted_kind", kHead2 + "circle 5 5 0.2 0.58 \"robot\"\n", "t.world:5: ",
     "circle: kind must be robot, post or obstacle, got '\"robot\"'"},
    {"circle_zero_height", kHead2 + "circle 5 5 0.2 0\n", "t.world:5: ", "circle: height must be > 0, got 0"},
    {"circle_too_many", kHead2 + "circle 5 5 0.2 0.5 robot 1\n", "t.world:5: ",
     "circle: expected 3 to 5 arguments (x y radius [height [kind]]), got 6"},
    {"ring_arguments", kHead2 + "ring 5 5\n", "t.world:5: ", "ring: expected 3 or 4 arguments (x y radius [width]), got 2"},
    {"ring_radius", kHead2 + "ring 5 5 -0.75\n", "t.world:5: ", "ring: radius must be > 0, got -0.75"},
    {"ring_width", kHead2 + "ring 5 5 0.75 0\n", "t.world:5: ", "ring: width must be > 0, got 0"},
    {"ring_width_too_wide", kHead2 + "ring 5 5 0.02\n", "t.world:5: ", "ring: width must be < the diameter"},
    {"ring_outside", kHead2 + "ring 12 5 1\n", "t.world:5: ", "ring: centre (12, 5) is outside the bounds"},
    {"lighting_arguments", kHead2 + "lighting 1 0.1 0.2\n", "t.world:5: ",
     "lighting: expected 5 or 6 arguments (brightness texture sun_strength sun_period sun_angle_deg [sun_phase]), got 3"},
    {"lighting_brightness", kHead2 + "lighting 0 0.1 0.2 2 30\n", "t.world:5: ",
     "lighting: brightness must be in [0.05, 4], got 0"},
    {"lighting_texture", kHead2 + "lighting 1 1.5 0.2 2 30\n", "t.world:5: ", "lighting: texture must be in [0, 1], got 1.5"},
    {"lighting_sun", kHead2 + "lighting 1 0.1 0.95 2 30\n", "t.world:5: ",
     "lighting: sun_strength must be in [0, 0.9], got 0.95"},
    {"lighting_period", kHead2 + "lighting 1 0.1 0.2 -2 30\n", "t.world:5: ", "lighting: sun_period must be > 0, got -2"},
    {"lighting_angle", kHead2 + "lighting 1 0.1 0.2 2 east\n", "t.world:5: ",
     "lighting: sun_angle_deg is not a number: 'east'"},
    {"lighting_twice", kHead2 + "lighting 1 0.1 0.2 2 30\nlighting 1 0.1 0.2 2 30\n", "t.world:6: ",
     "lighting: given twice (first on line 5)"},
    {"fractional_version", "ringlet-world 1.0\n", "t.world:1: ", "ringlet-world: version must be an integer, got '1.0'"},
    {"missing_version", "ringlet-world\n", "t.world:1: ", "ringlet-world: expected 1 argument (version), got 0"},
    {"missing_bounds", "ringlet-world 1\nstart 1 1 0\nball 2 2\n", "t.world:3: ", "end of file: missing 'bounds"},
    {"missing_start", "ringlet-world 1\nbounds 0 0 10 10\nball 2 2", "t.world:3: ", "end of file: missing 'start"},
    // Goals left the world format: an old file that still lists them is told where they go now.
    {"goal_refused", kHead + "goal 1 2\n", "t.world:5: ",
     "goal: goals belong to the mission, not the world: list them under [mission] goals in the firmware "
     "configuration"},
    {"goal_refused_before_the_end", "ringlet-world 1\ngoal 1 2\n", "t.world:2: ", "goal: goals belong to the mission"},
    {"start_outside", "ringlet-world 1\nbounds 0 0 10 10\nstart 11 5 0\n", "t.world:3: ",
     "start: (11, 5) is outside the bounds 0 0 10 10 (line 2)"},
    {"start_outside_before_bounds", "ringlet-world 1\nstart -1 1 0\nbounds 0 0 10 10\n", "t.world:2: ",
     "start: (-1, 1) is outside the bounds"},
    {"circle_outside", kHead + "circle 12 5 1\n", "t.world:5: ", "circle: centre (12, 5) is outside the bounds"},
    {"polygon_vertex_outside", kHead + "polygon 1 1 2 1 2 -3\n", "t.world:5: ",
     "polygon: vertex 3 (2, -3) is outside the bounds"},
    {"ball_outside", kHead + "ball 5 10.5\n", "t.world:5: ", "ball: (5, 10.5) is outside the bounds"},
    {"marking_outside", kHead + "marking 1 1 12 1\n", "t.world:5: ", "marking: end 2 (12, 1) is outside the bounds"},
    {"bow_tie_polygon", kHead + "polygon 1 1 3 3 3 1 1 3\n", "t.world:5: ", "polygon: self-intersecting: edges 1 and 3"},
    {"collinear_polygon", kHead + "polygon 1 1 2 2 3 3\n", "t.world:5: ", "polygon: self-intersecting"},
    {"polygon_touching_itself", kHead + "polygon 1 1 5 1 5 5 3 1 1 5\n", "t.world:5: ", "polygon: self-intersecting"},
    {"polygon_repeated_vertex", kHead + "polygon 1 1 2 2 2 2 1 3\n", "t.world:5: ",
     "polygon: vertices 2 and 3 are the same point"},
    {"polygon_two_vertices", kHead + "polygon 1 1 2 2\n", "t.world:5: ", "polygon: needs at least 3 vertices, got 2"},
    {"polygon_odd_coordinates", kHead + "polygon 1 1 2 2 3\n", "t.world:5: ",
     "polygon: expected x y pairs, got an odd number of coordinates (5)"},
    {"polygon_bad_number", kHead + "polygon 1 1 2 2 3 x\n", "t.world:5: ", "polygon: y3 is not a number: 'x'"},
    {"start_heading", "ringlet-world 1\nbounds 0 0 10 10\nstart 1 1 north\n", "t.world:3: ",
     "start: heading_deg is not a number: 'north'"},
};

// Test names and failure messages show the case's name, not the struct's bytes.
void PrintTo(const BadWorld& bad, std::ostream* out) { *out << bad.name; }

class SimWorldParserRejects : public testing::TestWithParam<BadWorld> {};

TEST_P(SimWorldParserRejects, WithPositionAndReason) {
  const BadWorld& bad = GetParam();
  const std::optional<std::string> message = world_error([&] { return parse_world(bad.text, "t.world"); });
  ASSERT_TRUE(message.has_value()) << "accepted:\n" << bad.text;
  EXPECT_EQ(message->substr(0, bad.position.size()), bad.position) << *message;
  EXPECT_NE(message->find(bad.phrase), std::string::npos) << *message;
}

INSTANTIATE_TEST_SUITE_P(SimWorldParser, SimWorldParserRejects, testing::ValuesIn(kBadWorlds),
                         [](const testing::TestParamInfo<BadWorld>& param) { return std::string(param.param.name); });

TEST(SimWorldParser, Version2ReadsRingsLightingAndObstacleHeights) {
  const World world = parse_world(kHead2 +
                                      "circle 2 2 0.3\n"
                                      "circle 3 3 0.15 0.58 robot\n"
                                      "circle 4 4 0.05 0.8 post\n"
                                      "circle 6 6 0.5 1.2\n"
                                      "ring 5 5 0.75\n"
                                      "ring 5 5 1 0.1\n"
                                      "lighting 0.9 0.1 0.3 2.5 45 0.25\n",
                                  "t.world");
  ASSERT_EQ(world.circles.size(), 4U);
  EXPECT_EQ(world.circles[0].height, 0.58);  // the default: a NAO's height
  EXPECT_EQ(world.circles[0].kind, ObstacleKind::kObstacle);
  EXPECT_EQ(world.circles[1].kind, ObstacleKind::kRobot);
  EXPECT_EQ(world.circles[2].kind, ObstacleKind::kPost);
  EXPECT_EQ(world.circles[2].height, 0.8);
  EXPECT_EQ(world.circles[3].height, 1.2);
  EXPECT_EQ(world.circles[3].kind, ObstacleKind::kObstacle);
  ASSERT_EQ(world.rings.size(), 2U);
  EXPECT_EQ(world.rings[0].radius, 0.75);
  EXPECT_EQ(world.rings[0].width, 0.05);
  EXPECT_EQ(world.rings[1].width, 0.1);
  EXPECT_EQ(world.lighting.brightness, 0.9);
  EXPECT_EQ(world.lighting.texture, 0.1);
  EXPECT_EQ(world.lighting.sun_strength, 0.3);
  EXPECT_EQ(world.lighting.sun_period, 2.5);
  EXPECT_DOUBLE_EQ(world.lighting.sun_angle, std::numbers::pi / 4.0);
  EXPECT_EQ(world.lighting.sun_phase, 0.25);
}

TEST(SimWorldParser, Version1FilesKeepTheirMeaning) {
  const World world = parse_world(kHead + "circle 2 2 0.3\n", "t.world");
  EXPECT_TRUE(world.rings.empty());
  EXPECT_EQ(world.lighting.sun_strength, 0.0);  // no stripes unless asked for
  EXPECT_EQ(world.circles[0].height, 0.58);
}

// Whole messages: a file that cannot be read names its path and the reason; a bad statement's
// message is exactly "<source>:<line>: <message>".
struct ExactError {
  const char* name;
  std::function<World()> load;
  std::string message;
};

const ExactError kExactErrors[] = {
    {"MissingFileNamesThePathAndTheReason", [] { return load_world(kTestWorlds + "/no-such.world"); },
     kTestWorlds + "/no-such.world: cannot read world file: No such file or directory"},
    {"DirectoryIsNotAWorldFile", [] { return load_world(kTestWorlds); },
     kTestWorlds + ": cannot read world file: not a regular file (a directory)"},
    {"MessageIsExactlySourceLineMessage", [] { return parse_world(kHead + "\n\ncircle 5 7 -1\n", "courtyard.world"); },
     "courtyard.world:7: circle: radius must be > 0, got -1"},
};

void PrintTo(const ExactError& exact, std::ostream* out) { *out << exact.name; }

class SimWorldParserExactError : public testing::TestWithParam<ExactError> {};

TEST_P(SimWorldParserExactError, Is) {
  const std::optional<std::string> message = world_error(GetParam().load);
  ASSERT_TRUE(message.has_value()) << "no exception";
  EXPECT_EQ(*message, GetParam().message);
}

INSTANTIATE_TEST_SUITE_P(SimWorldParser, SimWorldParserExactError, testing::ValuesIn(kExactErrors),
                         [](const testing::TestParamInfo<ExactError>& param) { return std::string(param.param.name); });

}  // namespace
}  // namespace ringlet::sim_hal
