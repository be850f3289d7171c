// The world file reader: one statement per line, checked as it is read; the checks that need the
// bounds run after the last line, because the format does not force bounds to come first.
// Everything goes into a local World that is returned only when the whole file was accepted.
#include <cmath>
#include <span>
#include <string>
#include <vector>

#include "polygon_check.hpp"
#include "ringlet/hal/read_file.hpp"
#include "ringlet/sim_hal/world.hpp"
#include "world_lexer.hpp"

namespace ringlet::sim_hal {
namespace {

using detail::Token;

constexpr std::string_view kHeaderKeyword = "ringlet-world";

struct Statement {
  int line = 0;
  std::string_view keyword;
  std::span<const Token> args;
};

/// A point that must lie inside the bounds. Checked after the last line, in file order.
struct PlacedPoint {
  int line = 0;
  std::string_view keyword;
  std::string label;  // "centre", "vertex 3", ... or empty when the object is a single point
  Token x;
  Token y;
  Vec2 at;
};

/// An angle in degrees as radians in (-pi, pi]. Reduced in degrees first (exact for any finite
/// value, and a no-op within +-180): a huge but finite angle such as 1e308 overflows to infinity
/// in radians, which wraps to NaN (found by the world fuzz target).
double heading_rad(double degrees) {
  return hal::wrap_angle(hal::deg_to_rad(std::remainder(degrees, 360.0)));
}

/// A token as the author wrote it, for quoting it back in a message.
std::string as_written(const Token& token) {
  return token.quoted ? "\"" + std::string(token.text) + "\"" : std::string(token.text);
}

class WorldParser {
 public:
  explicit WorldParser(std::string_view source) : source_(source) {}

  World parse(std::string_view text) {
    std::vector<Token> tokens;
    int line = 0;
    std::size_t pos = 0;
    while (pos < text.size()) {
      ++line;
      const std::size_t newline = text.find('\n', pos);
      const std::size_t end = newline == std::string_view::npos ? text.size() : newline;
      if (const auto error = detail::split_tokens(text.substr(pos, end - pos), tokens)) fail(line, *error);
      pos = end + 1;
      if (tokens.empty()) continue;
      if (tokens.front().quoted) fail(line, "unknown keyword " + as_written(tokens.front()));
      dispatch(Statement{line, tokens.front().text, std::span<const Token>(tokens).subspan(1)});
    }
    check_complete(line < 1 ? 1 : line);
    check_inside_bounds();
    return std::move(world_);
  }

 private:
  [[noreturn]] void fail(int line, std::string_view message) const {
    throw WorldError(std::string(source_) + ":" + std::to_string(line) + ": " + std::string(message));
  }

  void dispatch(const Statement& s) {
    if (header_line_ == 0) {
      if (s.keyword != kHeaderKeyword) {
        fail(s.line, "missing header: the first line must be 'ringlet-world " +
                         std::to_string(World::kFormatVersion) + "', got '" + std::string(s.keyword) + "'");
      }
      header(s);
    } else if (s.keyword == kHeaderKeyword) {
      duplicate(s, header_line_);
    } else if (s.keyword == "name") {
      name(s);
    } else if (s.keyword == "bounds") {
      bounds(s);
    } else if (s.keyword == "start") {
      start(s);
    } else if (s.keyword == "circle") {
      circle(s);
    } else if (s.keyword == "polygon") {
      polygon(s);
    } else if (s.keyword == "marking") {
      marking(s);
    } else if (s.keyword == "ring") {
      ring(s);
    } else if (s.keyword == "lighting") {
      lighting(s);
    } else if (s.keyword == "look") {
      look(s);
    } else if (s.keyword == "ball") {
      ball(s);
    } else if (s.keyword == "goal") {
      fail(s.line, "goal: goals belong to the mission, not the world: list them under [mission] goals in the "
                   "firmware configuration");
    } else {
      fail(s.line, "unknown keyword '" + std::string(s.keyword) +
                       "' (expected name, bounds, start, circle, polygon, marking, ring, lighting, look or ball)");
    }
  }

  // --- argument helpers -------------------------------------------------------------------------

  std::string prefix(const Statement& s) const { return std::string(s.keyword) + ": "; }

  void expect_args(const Statement& s, std::size_t min, std::size_t max, std::string_view usage) const {
    const std::size_t got = s.args.size();
    if (got >= min && got <= max) return;
    const std::string count = min == max       ? std::to_string(min)
                              : max == min + 1 ? std::to_string(min) + " or " + std::to_string(max)
                                               : std::to_string(min) + " to " + std::to_string(max);
    fail(s.line, prefix(s) + "expected " + count + (max == 1 ? " argument" : " arguments") + " (" +
                     std::string(usage) + "), got " + std::to_string(got));
  }

  double number(const Statement& s, std::size_t index, std::string_view what) const {
    const Token& token = s.args[index];
    const detail::NumberResult result = detail::parse_number(token);
    using Status = detail::NumberResult::Status;
    switch (result.status) {
      case Status::kOk:
        return result.value;
      case Status::kOutOfRange:
        fail(s.line, prefix(s) + std::string(what) + " is out of range: '" + as_written(token) + "'");
      case Status::kNotFinite:
        fail(s.line, prefix(s) + std::string(what) + " must be finite, got '" + as_written(token) + "'");
      case Status::kNotANumber:
        break;
    }
    fail(s.line, prefix(s) + std::string(what) + " is not a number: '" + as_written(token) + "'");
  }

  double positive(const Statement& s, std::size_t index, std::string_view what) const {
    const double value = number(s, index, what);
    if (!(value > 0.0)) {
      fail(s.line, prefix(s) + std::string(what) + " must be > 0, got " + as_written(s.args[index]));
    }
    return value;
  }

  Vec2 point(const Statement& s, std::size_t index, std::string_view x_name, std::string_view y_name,
             std::string label) {
    const Vec2 at{number(s, index, x_name), number(s, index + 1, y_name)};
    placed_.push_back(PlacedPoint{s.line, s.keyword, std::move(label), s.args[index], s.args[index + 1], at});
    return at;
  }

  [[noreturn]] void duplicate(const Statement& s, int first_line) const {
    fail(s.line, prefix(s) + "given twice (first on line " + std::to_string(first_line) + ")");
  }

  // --- statements -------------------------------------------------------------------------------

  void header(const Statement& s) {
    expect_args(s, 1, 1, "version");
    const std::optional<int> version = detail::parse_integer(s.args[0]);
    if (!version) fail(s.line, prefix(s) + "version must be an integer, got '" + as_written(s.args[0]) + "'");
    if (*version < World::kMinFormatVersion || *version > World::kFormatVersion) {
      fail(s.line, prefix(s) + "unsupported version " + std::to_string(*version) + " (this build reads versions " +
                       std::to_string(World::kMinFormatVersion) + " to " + std::to_string(World::kFormatVersion) + ")");
    }
    header_line_ = s.line;
    version_ = *version;
  }

  void name(const Statement& s) {
    if (name_line_ != 0) duplicate(s, name_line_);
    if (s.args.size() != 1 || !s.args[0].quoted) {
      fail(s.line, prefix(s) + "expected one quoted string, e.g. name \"Courtyard\"");
    }
    world_.name = std::string(s.args[0].text);
    name_line_ = s.line;
  }

  void bounds(const Statement& s) {
    if (bounds_line_ != 0) duplicate(s, bounds_line_);
    expect_args(s, 4, 4, "xmin ymin xmax ymax");
    const Vec2 min{number(s, 0, "xmin"), number(s, 1, "ymin")};
    const Vec2 max{number(s, 2, "xmax"), number(s, 3, "ymax")};
    if (!(min.x < max.x)) {
      fail(s.line, prefix(s) + "xmin (" + as_written(s.args[0]) + ") must be < xmax (" + as_written(s.args[2]) + ")");
    }
    if (!(min.y < max.y)) {
      fail(s.line, prefix(s) + "ymin (" + as_written(s.args[1]) + ") must be < ymax (" + as_written(s.args[3]) + ")");
    }
    world_.min = min;
    world_.max = max;
    bounds_text_ = std::string(s.args[0].text) + " " + std::string(s.args[1].text) + " " +
                   std::string(s.args[2].text) + " " + std::string(s.args[3].text);
    bounds_line_ = s.line;
  }

  void start(const Statement& s) {
    if (start_line_ != 0) duplicate(s, start_line_);
    expect_args(s, 3, 3, "x y heading_deg");
    const Vec2 at = point(s, 0, "x", "y", "");
    const double heading_deg = number(s, 2, "heading_deg");
    world_.start = hal::Pose2{at.x, at.y, heading_rad(heading_deg)};
    world_.start_line = s.line;
    start_line_ = s.line;
  }

  /// Statements and arguments added by format version 2 are refused in a version 1 file, so a
  /// version 1 file means exactly what it meant before.
  void require_version_2(const Statement& s, std::string_view what) const {
    if (version_ >= 2) return;
    fail(s.line, prefix(s) + std::string(what) + " needs format version 2 (the header on line " +
                     std::to_string(header_line_) + " says " + std::to_string(version_) + ")");
  }

  double in_range(const Statement& s, std::size_t index, std::string_view what, double lo, double hi,
                  std::string_view rule) const {
    const double value = number(s, index, what);
    if (!(value >= lo && value <= hi)) {
      fail(s.line, prefix(s) + std::string(what) + " must be " + std::string(rule) + ", got " + as_written(s.args[index]));
    }
    return value;
  }

  void circle(const Statement& s) {
    expect_args(s, 3, 5, "x y radius [height [kind]]");
    if (s.args.size() > 3) require_version_2(s, "height and kind");
    Circle result;
    result.centre = point(s, 0, "x", "y", "centre");
    result.radius = positive(s, 2, "radius");
    if (s.args.size() >= 4) result.height = positive(s, 3, "height");
    if (s.args.size() == 5) {
      const Token& kind = s.args[4];
      if (!kind.quoted && kind.text == "robot") {
        result.kind = ObstacleKind::kRobot;
      } else if (!kind.quoted && kind.text == "post") {
        result.kind = ObstacleKind::kPost;
      } else if (!kind.quoted && kind.text == "obstacle") {
        result.kind = ObstacleKind::kObstacle;
      } else {
        fail(s.line, prefix(s) + "kind must be robot, post or obstacle, got '" + as_written(kind) + "'");
      }
    }
    world_.circles.push_back(result);
  }

  void ring(const Statement& s) {
    require_version_2(s, "this statement");
    expect_args(s, 3, 4, "x y radius [width]");
    Ring result;
    result.centre = point(s, 0, "x", "y", "centre");
    result.radius = positive(s, 2, "radius");
    if (s.args.size() == 4) result.width = positive(s, 3, "width");
    if (!(result.width < 2.0 * result.radius)) {
      fail(s.line, prefix(s) + "width must be < the diameter (2 x radius)");
    }
    world_.rings.push_back(result);
  }

  void lighting(const Statement& s) {
    require_version_2(s, "this statement");
    if (lighting_line_ != 0) duplicate(s, lighting_line_);
    expect_args(s, 5, 6, "brightness texture sun_strength sun_period sun_angle_deg [sun_phase]");
    Lighting result;
    result.brightness = in_range(s, 0, "brightness", 0.05, 4.0, "in [0.05, 4]");
    result.texture = in_range(s, 1, "texture", 0.0, 1.0, "in [0, 1]");
    result.sun_strength = in_range(s, 2, "sun_strength", 0.0, 0.9, "in [0, 0.9]");
    result.sun_period = positive(s, 3, "sun_period");
    result.sun_angle = heading_rad(number(s, 4, "sun_angle_deg"));
    if (s.args.size() == 6) result.sun_phase = number(s, 5, "sun_phase");
    world_.lighting = result;
    lighting_line_ = s.line;
  }

  /// look STYLE [BALL [LIGHT]]: the camera's look (camera_look.hpp). A version 2 statement added
  /// later: an older build refuses it as an unknown keyword, so no build misreads a file.
  void look(const Statement& s) {
    require_version_2(s, "this statement");
    if (look_line_ != 0) duplicate(s, look_line_);
    expect_args(s, 1, 3, "style [ball [light]]");
    CameraLook result;
    const auto word = [&](std::size_t i) { return s.args[i].quoted ? std::string_view{} : s.args[i].text; };
    if (word(0) == "plain") {
      result.style = LookStyle::kPlain;
    } else if (word(0) == "spl") {
      result.style = LookStyle::kSpl;
      result.ball = BallLook::kBlackWhite;
      result.drift = 0.04;  // a real camera's auto exposure and white balance hunt a little
    } else {
      fail(s.line, prefix(s) + "style must be plain or spl, got '" + as_written(s.args[0]) + "'");
    }
    if (s.args.size() >= 2) {
      if (word(1) == "orange") {
        result.ball = BallLook::kOrange;
      } else if (word(1) == "bw") {
        result.ball = BallLook::kBlackWhite;
      } else {
        fail(s.line, prefix(s) + "ball must be orange or bw, got '" + as_written(s.args[1]) + "'");
      }
    }
    if (s.args.size() == 3) {
      if (word(2) == "fluorescent") {
        result.light = LightKind::kFluorescent;
      } else if (word(2) == "daylight") {
        result.light = LightKind::kDaylight;
      } else if (word(2) == "backlight") {
        result.light = LightKind::kBacklight;
        result.exposure = 0.7;  // the camera exposes for the bright windows
      } else {
        fail(s.line, prefix(s) + "light must be fluorescent, daylight or backlight, got '" + as_written(s.args[2]) + "'");
      }
    }
    world_.look = result;
    look_line_ = s.line;
  }

  void polygon(const Statement& s) {
    if (s.args.size() % 2 != 0) {
      fail(s.line, prefix(s) + "expected x y pairs, got an odd number of coordinates (" +
                       std::to_string(s.args.size()) + ")");
    }
    const std::size_t count = s.args.size() / 2;
    if (count < 3) fail(s.line, prefix(s) + "needs at least 3 vertices, got " + std::to_string(count));
    Polygon result;
    result.vertices.reserve(count);
    for (std::size_t i = 0; i < count; ++i) {
      const std::string n = std::to_string(i + 1);
      result.vertices.push_back(point(s, 2 * i, "x" + n, "y" + n, "vertex " + n));
    }
    if (const auto defect = detail::find_polygon_defect(result.vertices)) {
      const std::string first = std::to_string(defect->first + 1);
      const std::string second = std::to_string(defect->second + 1);
      if (defect->kind == detail::PolygonDefect::Kind::kRepeatedVertex) {
        fail(s.line, prefix(s) + "vertices " + first + " and " + second + " are the same point");
      }
      fail(s.line, prefix(s) + "self-intersecting: edges " + first + " and " + second +
                       " overlap (edge i runs from vertex i to the next)");
    }
    world_.polygons.push_back(std::move(result));
  }

  void marking(const Statement& s) {
    expect_args(s, 4, 5, "x1 y1 x2 y2 [width]");
    Marking result;
    result.a = point(s, 0, "x1", "y1", "end 1");
    result.b = point(s, 2, "x2", "y2", "end 2");
    if (s.args.size() == 5) result.width = positive(s, 4, "width");
    if (result.a.x == result.b.x && result.a.y == result.b.y) {
      fail(s.line, prefix(s) + "the two end points are the same, a line needs length");
    }
    world_.markings.push_back(result);
  }

  void ball(const Statement& s) {
    if (ball_line_ != 0) duplicate(s, ball_line_);
    expect_args(s, 2, 3, "x y [radius]");
    Ball result;
    result.position = point(s, 0, "x", "y", "");
    if (s.args.size() == 3) result.radius = positive(s, 2, "radius");
    world_.ball = result;
    ball_line_ = s.line;
  }

  // --- whole-file checks ------------------------------------------------------------------------

  void check_complete(int eof_line) const {
    if (header_line_ == 0) {
      fail(eof_line, "end of file: missing header 'ringlet-world " + std::to_string(World::kFormatVersion) + "'");
    }
    if (bounds_line_ == 0) fail(eof_line, "end of file: missing 'bounds <xmin> <ymin> <xmax> <ymax>' (required once)");
    if (start_line_ == 0) fail(eof_line, "end of file: missing 'start <x> <y> <heading_deg>' (required once)");
  }

  void check_inside_bounds() const {
    for (const PlacedPoint& p : placed_) {
      const bool inside =
          p.at.x >= world_.min.x && p.at.x <= world_.max.x && p.at.y >= world_.min.y && p.at.y <= world_.max.y;
      if (inside) continue;
      const std::string label = p.label.empty() ? "" : p.label + " ";
      fail(p.line, std::string(p.keyword) + ": " + label + "(" + std::string(p.x.text) + ", " +
                       std::string(p.y.text) + ") is outside the bounds " + bounds_text_ + " (line " +
                       std::to_string(bounds_line_) + ")");
    }
  }

  std::string_view source_;
  World world_;
  int header_line_ = 0;
  int name_line_ = 0;
  int bounds_line_ = 0;
  int start_line_ = 0;
  int ball_line_ = 0;
  int lighting_line_ = 0;
  int look_line_ = 0;
  int version_ = 0;
  std::string bounds_text_;
  std::vector<PlacedPoint> placed_;
};

}  // namespace

World parse_world(std::string_view text, std::string_view source) { return WorldParser(source).parse(text); }

World load_world(const std::filesystem::path& path) {
  // Bounded: a directory, a FIFO or /dev/zero is refused before a byte is read.
  const hal::FileRead file = hal::read_file(path, "world file");
  if (!file.ok()) throw WorldError(file.error);
  return parse_world(file.bytes, path.string());
}

}  // namespace ringlet::sim_hal
