// The SVG picture: what is drawn (the mission's goals, trajectory, collisions: all from the
// hal::RunPicture, none from the world), that y points up, that output is deterministic, and that
// a file that cannot be written is reported.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "ringlet/sim_hal/world_svg.hpp"
#include "sim_test_support.hpp"

namespace ringlet::sim_hal {
namespace {

std::size_t count(const std::string& text, const std::string& needle) {
  std::size_t n = 0;
  for (std::size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + needle.size())) ++n;
  return n;
}

/// The value of the first `name="..."` attribute after `from`.
std::string attribute(const std::string& text, const std::string& name, std::size_t from = 0) {
  const std::size_t start = text.find(" " + name + "=\"", from);
  if (start == std::string::npos) return {};
  const std::size_t value = start + name.size() + 3;
  return text.substr(value, text.find('"', value) - value);
}

World picture_world() {
  World world = test::box_world(20.0, 10.0, {1.0, 1.0, 0.0});
  world.name = "Yard <A & B>";
  world.circles.push_back({{10.0, 5.0}, 1.0});
  world.polygons.push_back({{{2.0, 7.0}, {4.0, 7.0}, {3.0, 9.0}}});
  world.markings.push_back({{1.0, 5.0}, {19.0, 5.0}, 0.05});
  world.ball = Ball{{12.0, 3.0}, 0.05};
  return world;
}

/// The mission's goals for picture_world(), in order.
const std::vector<hal::WorldPoint> kGoals = {{5.0, 5.0}, {15.0, 8.0}, {15.0, 2.0}, {5.0, 2.0}};

/// A picture of a run with the four goals, none reached yet.
hal::RunPicture with_goals() {
  hal::RunPicture picture;
  picture.goals = kGoals;
  return picture;
}

std::vector<hal::Pose2> spiral(std::size_t n) {
  std::vector<hal::Pose2> poses;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) * 0.1;
    poses.push_back({10.0 + 0.1 * t * std::sin(t), 5.0 + 0.1 * t * std::cos(t), t});
  }
  return poses;
}

std::string render(const World& world, const hal::RunPicture& overlay) {
  std::ostringstream out;
  write_world_svg(out, world, overlay);
  return out.str();
}

TEST(SimSvg, DrawsGoalsReachedAndPending) {
  const World world = picture_world();
  hal::RunPicture overlay = with_goals();
  overlay.goals_reached = 3;
  const std::string svg = render(world, overlay);
  EXPECT_EQ(count(svg, "<circle class=\"goal reached\""), 3U);
  EXPECT_EQ(count(svg, "<circle class=\"goal\""), 1U);
  EXPECT_NE(svg.find(">4</text>"), std::string::npos);  // goals are numbered from 1
  EXPECT_EQ(svg.find(">5</text>"), std::string::npos);
}

// The world has no goals of its own: a picture without the mission's shows none.
TEST(SimSvg, DrawsNoGoalsWhenThePictureHasNone) {
  const std::string svg = render(picture_world(), hal::RunPicture{});
  EXPECT_EQ(count(svg, "class=\"goal"), 0U);
  EXPECT_EQ(svg.find(">1</text>"), std::string::npos);
  EXPECT_EQ(count(svg, "class=\"obstacle\""), 2U);  // the world itself is still drawn
}

TEST(SimSvg, TrajectoryIsOnePolylineWithEveryPoint) {
  const World world = picture_world();
  const std::vector<hal::Pose2> poses = spiral(57);
  hal::RunPicture overlay;
  overlay.trajectory = poses;
  const std::string svg = render(world, overlay);
  ASSERT_EQ(count(svg, "<polyline class=\"trajectory\""), 1U);
  const std::string points = attribute(svg, "points", svg.find("<polyline"));
  EXPECT_EQ(count(points, ",") , 57U);
  EXPECT_EQ(count(points, " "), 56U);

  overlay.trajectory = {};
  EXPECT_EQ(count(render(world, overlay), "<polyline"), 0U);
}

TEST(SimSvg, ScaleIsAbout900PixelsAndYPointsUp) {
  const World world = picture_world();
  const std::string svg = render(world, with_goals());
  // The 20 m wide world is 900 px wide: 45 px per metre, goal 1 at (5, 5) and goal 2 at (15, 8).
  const std::size_t first = svg.find("<circle class=\"goal\"");
  const std::size_t second = svg.find("<circle class=\"goal\"", first + 1);
  const double x1 = std::stod(attribute(svg, "cx", first));
  const double x2 = std::stod(attribute(svg, "cx", second));
  const double y1 = std::stod(attribute(svg, "cy", first));
  const double y2 = std::stod(attribute(svg, "cy", second));
  EXPECT_DOUBLE_EQ(x2 - x1, 450.0);
  EXPECT_DOUBLE_EQ(y1 - y2, 135.0);  // the higher goal is nearer the top of the picture
}

TEST(SimSvg, DrawsEveryKindOfThing) {
  const World world = picture_world();
  const std::vector<hal::WorldPoint> hits = {{10.0, 3.8}, {3.0, 6.6}, {18.0, 9.0}};
  hal::RunPicture overlay = with_goals();
  overlay.collisions = hits;
  overlay.caption = "mission: 3/4 goals & 3 collisions <bad>";
  const std::string svg = render(world, overlay);
  EXPECT_TRUE(svg.starts_with("<?xml"));
  EXPECT_NE(svg.find("<svg xmlns=\"http://www.w3.org/2000/svg\""), std::string::npos);
  EXPECT_TRUE(svg.ends_with("</svg>\n"));
  EXPECT_EQ(count(svg, "class=\"collision\""), 3U);
  EXPECT_EQ(count(svg, "class=\"obstacle\""), 2U);
  EXPECT_EQ(count(svg, "class=\"marking\""), 1U);
  EXPECT_EQ(count(svg, "class=\"ball\""), 1U);
  EXPECT_EQ(count(svg, "class=\"start\""), 1U);
  EXPECT_EQ(count(svg, "class=\"scale-bar\""), 3U);
  EXPECT_NE(svg.find(">1 m</text>"), std::string::npos);
  EXPECT_NE(svg.find("mission: 3/4 goals &amp; 3 collisions &lt;bad&gt;"), std::string::npos);
  EXPECT_NE(svg.find("<title>Yard &lt;A &amp; B&gt;</title>"), std::string::npos);
  EXPECT_NE(svg.find("fill=\"#6aa84f\""), std::string::npos);  // grass under the markings
}

// A task planner's picture has no map: its places by name, its plans through them and the obstacles
// the controller reported, with a legend row for what is there and none for a map it lacks.
TEST(SimSvg, DrawsATaskPlannersPlacesPlansAndReportedObstacles) {
  const World world = picture_world();
  const std::vector<hal::NamedPoint> places = {{{2.0, 2.0}, "p11"}, {{6.0, 2.0}, "p<21>"}, {{6.0, 6.0}, "p22"}};
  const std::vector<hal::WorldPoint> points = {{2.0, 2.0}, {6.0, 2.0}, {6.0, 2.0}, {6.0, 6.0}};
  const std::vector<std::uint32_t> ends = {2, 4};
  const std::vector<hal::WorldPoint> reported = {{4.0, 2.1}};
  hal::RunPicture overlay = with_goals();
  overlay.plans.places = places;
  overlay.plans.plan_points = points;
  overlay.plans.plan_ends = ends;
  overlay.plans.reported = reported;
  const std::string svg = render(world, overlay);
  EXPECT_EQ(count(svg, "class=\"place\""), 6U) << "a ring and a name each";
  EXPECT_NE(svg.find(">p&lt;21&gt;</text>"), std::string::npos);
  EXPECT_EQ(count(svg, "class=\"plan\""), 2U);
  EXPECT_EQ(count(svg, "class=\"reported\""), 1U);
  EXPECT_NE(svg.find(">place (PDDL object)</text>"), std::string::npos);
  EXPECT_NE(svg.find(">obstacle reported to the planner</text>"), std::string::npos);
  EXPECT_EQ(svg.find("occupied cell"), std::string::npos) << "no map, no map legend";
  EXPECT_EQ(svg.find("class=\"region-grid\""), std::string::npos);
  const std::string plain = render(world, with_goals());
  EXPECT_EQ(plain.find("first plan"), std::string::npos) << "no planner, no planner row";
  EXPECT_LT(std::stod(attribute(plain, "height")), std::stod(attribute(svg, "height")));
}

TEST(SimSvg, DrawsTrueAndEstimatedTrajectoriesParticlesAndTheLinesThatDroveACorrection) {
  const World world = picture_world();
  const std::vector<hal::Pose2> estimated = {{2.0, 2.0, 0.0}, {2.0, 4.0, 0.0}, {2.1, 6.0, 0.0}};
  const std::vector<hal::Pose2> truth = {{2.0, 2.0, 0.0}, {2.05, 4.0, 0.0}, {2.0, 6.0, 0.0}, {2.0, 7.0, 0.0}};
  // Two snapshots: three particles then two; one segment then none.
  const std::vector<hal::Pose2> particles = {{2.0, 2.0, 0.0}, {2.1, 2.0, 0.5}, {1.9, 2.1, 0.0}, {2.0, 6.0, 1.57}, {2.0, 6.1, 1.57}};
  const std::vector<hal::WorldSegment> segments = {{{1.0, 3.0}, {3.0, 3.0}}};
  const std::vector<hal::LocalizationSnapshot> snapshots = {{0.5, {2.0, 2.0, 0.0}, 3, 1, "start"},
                                                            {12.34, {2.0, 6.0, 0.0}, 5, 1, "relocalized"}};
  hal::RunPicture overlay = with_goals();
  overlay.trajectory = estimated;
  overlay.localization.truth = truth;
  overlay.localization.snapshots = snapshots;
  overlay.localization.particles = particles;
  overlay.localization.segments = segments;
  const std::string svg = render(world, overlay);
  EXPECT_EQ(count(svg, "class=\"truth\""), 1U);
  EXPECT_EQ(count(svg, "class=\"trajectory\""), 1U);
  EXPECT_NE(attribute(svg, "stroke", svg.find("class=\"truth\"")), attribute(svg, "stroke", svg.find("class=\"trajectory\"")))
      << "the true and the estimated trajectories in different colours";
  // The true path's four points, y up: (2, 7) is 3 m above (2, 4).
  EXPECT_EQ(count(attribute(svg, "points", svg.find("class=\"truth\"")), ","), 4U);
  EXPECT_EQ(count(svg, "class=\"particles\""), 2U);
  const std::string first_cloud = attribute(svg, "d", svg.find("class=\"particles\""));
  EXPECT_EQ(count(first_cloud, "M"), 3U) << "a stroke per particle of the first snapshot";
  EXPECT_EQ(count(svg, "<line class=\"observed\""), 1U);
  EXPECT_EQ(count(svg, "class=\"snapshot\""), 2U);
  EXPECT_NE(svg.find(">0.5 s start</text>"), std::string::npos);
  EXPECT_NE(svg.find(">12.3 s relocalized</text>"), std::string::npos);
  EXPECT_NE(svg.find(">estimated trajectory</text>"), std::string::npos);
  EXPECT_NE(svg.find(">true trajectory (simulator)</text>"), std::string::npos);
  EXPECT_NE(svg.find(">particles at a snapshot (time, why)</text>"), std::string::npos);
  EXPECT_NE(svg.find(">lines seen then, placed by the estimate</text>"), std::string::npos);
  hal::RunPicture plain = with_goals();
  plain.trajectory = estimated;
  const std::string without = render(world, plain);
  EXPECT_EQ(without.find("class=\"truth\""), std::string::npos);
  EXPECT_EQ(without.find("true trajectory"), std::string::npos) << "no localization, no localization row";
  EXPECT_NE(without.find(">trajectory</text>"), std::string::npos);
  EXPECT_LT(std::stod(attribute(without, "height")), std::stod(attribute(svg, "height")));
}

TEST(SimSvg, DrawsPaintedRingsAsCirclesOnGrass) {
  World world = test::box_world(10.0, 10.0, {1.0, 1.0, 0.0});
  world.rings.push_back(Ring{{5.0, 5.0}, 0.75, 0.05});
  const std::string svg = render(world, hal::RunPicture{});
  EXPECT_EQ(count(svg, "class=\"marking\""), 1U);
  EXPECT_NE(svg.find("fill=\"none\" stroke=\"#ffffff\""), std::string::npos);
  EXPECT_NE(svg.find("fill=\"#6aa84f\""), std::string::npos);
}

TEST(SimSvg, IsDeterministicAndTheFileMatchesTheStream) {
  const World world = picture_world();
  const std::vector<hal::Pose2> poses = spiral(200);
  const std::vector<hal::WorldPoint> hits = {{10.0, 3.8}};
  const hal::RunPicture overlay{poses, hits, kGoals, 2, "caption"};
  const std::string first = render(world, overlay);
  EXPECT_EQ(first, render(world, overlay));

  const std::filesystem::path path = std::filesystem::path(testing::TempDir()) / "ringlet_sim_svg_test.svg";
  write_world_svg(path, world, overlay);
  std::ifstream in(path, std::ios::binary);
  const std::string from_file{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  EXPECT_EQ(from_file, first);
  std::filesystem::remove(path);
}

TEST(SimSvg, UnwritableFileNamesThePath) {
  const std::filesystem::path path = "/nonexistent-ringlet-dir/picture.svg";
  try {
    write_world_svg(path, picture_world(), with_goals());
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), path.string() + ": cannot write SVG: No such file or directory");
  }
}

}  // namespace
}  // namespace ringlet::sim_hal
