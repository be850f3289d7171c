// A self-contained SVG of a world and a run in it. The picture is built in a string with every
// number printed the same fixed way, so the same inputs always give byte-identical files (they
// end up in reports and diffs).
#include "ringlet/sim_hal/world_svg.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <fstream>
#include <span>
#include <stdexcept>
#include <string>
#include <system_error>

#include "number_text.hpp"

namespace ringlet::sim_hal {
namespace {

constexpr double kWorldWidthPx = 900.0;
constexpr double kMarginPx = 30.0;
constexpr double kFooterPx = 100.0;
constexpr double kGoalRadiusM = 0.3;  // the usual goal tolerance, so "reached" looks like it

constexpr const char* kObstacleFill = "#4a4a4a";
constexpr const char* kTrajectoryStroke = "#1f5fd1";
constexpr const char* kPlanStroke = "#e07b00";
constexpr const char* kOccupiedFill = "#8e2a1e";
constexpr const char* kGoalColour = "#1e8c4a";
constexpr const char* kStartFill = "#7b3fb5";
constexpr const char* kCollisionStroke = "#d62020";
constexpr const char* kPlaceColour = "#5a5a5a";
constexpr const char* kReportedFill = "#f2c200";
constexpr const char* kTruthStroke = "#111111";
constexpr const char* kParticleStroke = "#e0218a";
constexpr const char* kObservedStroke = "#00c8ff";

/// ~900 px across the world. A World that did not come from the parser may have empty bounds;
/// it still gets a (meaningless but finite) picture rather than NaN coordinates.
double pixels_per_metre(const World& world) {
  const double width = world.max.x - world.min.x;
  return width > 0.0 && std::isfinite(width) ? kWorldWidthPx / width : 1.0;
}

class SvgPicture {
 public:
  SvgPicture(const World& world, const hal::RunPicture& overlay)
      : world_(world), overlay_(overlay), scale_(pixels_per_metre(world)) {}

  std::string draw() {
    const double width = kWorldWidthPx + 2.0 * kMarginPx;
    const double height = kMarginPx + world_px_height() + kFooterPx + (has_plan_row() ? 24.0 : 0.0) +
                          (has_localization_row() ? 24.0 : 0.0);
    text_ += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\"";
    attr("width", width);
    attr("height", height);
    text_ += " viewBox=\"0 0 ";
    number(width);
    text_ += ' ';
    number(height);
    text_ += "\" font-family=\"sans-serif\" font-size=\"13\">\n<title>";
    escaped(world_.name.empty() ? std::string_view("Ringlet world") : std::string_view(world_.name));
    text_ += "</title>\n";
    rect("background", 0.0, 0.0, width, height, "fill=\"#f5f5f2\"");
    ground();
    markings();
    obstacles();
    ball();
    plan_map();
    places();
    plans();
    particles();
    truth();
    trajectory();
    observed();
    reported();
    goals();
    start_pose();
    collisions();
    footer();
    text_ += "</svg>\n";
    return std::move(text_);
  }

 private:
  // --- coordinates and output primitives ---------------------------------------------------------

  [[nodiscard]] double world_px_width() const { return (world_.max.x - world_.min.x) * scale_; }
  [[nodiscard]] double world_px_height() const { return (world_.max.y - world_.min.y) * scale_; }
  [[nodiscard]] double px(double x) const { return kMarginPx + (x - world_.min.x) * scale_; }
  // SVG's y grows downwards; the world's grows upwards.
  [[nodiscard]] double py(double y) const { return kMarginPx + (world_.max.y - y) * scale_; }

  void number(double value) { detail::append_fixed(text_, value, 3); }

  void attr(std::string_view name, double value) {
    text_ += ' ';
    text_ += name;
    text_ += "=\"";
    number(value);
    text_ += '"';
  }

  void point(double x_px, double y_px) {
    number(x_px);
    text_ += ',';
    number(y_px);
  }

  void escaped(std::string_view raw) {
    for (const char c : raw) {
      switch (c) {
        case '&': text_ += "&amp;"; break;
        case '<': text_ += "&lt;"; break;
        case '>': text_ += "&gt;"; break;
        case '"': text_ += "&quot;"; break;
        case '\'': text_ += "&apos;"; break;
        default: text_ += c;
      }
    }
  }

  void rect(std::string_view cls, double x, double y, double w, double h, std::string_view style) {
    text_ += "<rect class=\"";
    text_ += cls;
    text_ += '"';
    attr("x", x);
    attr("y", y);
    attr("width", w);
    attr("height", h);
    text_ += ' ';
    text_ += style;
    text_ += "/>\n";
  }

  void circle(std::string_view cls, double cx, double cy, double r, std::string_view style) {
    text_ += "<circle class=\"";
    text_ += cls;
    text_ += '"';
    attr("cx", cx);
    attr("cy", cy);
    attr("r", r);
    text_ += ' ';
    text_ += style;
    text_ += "/>\n";
  }

  void line(std::string_view cls, double x1, double y1, double x2, double y2, std::string_view style) {
    text_ += "<line class=\"";
    text_ += cls;
    text_ += '"';
    attr("x1", x1);
    attr("y1", y1);
    attr("x2", x2);
    attr("y2", y2);
    text_ += ' ';
    text_ += style;
    text_ += "/>\n";
  }

  void label(double x, double y, std::string_view anchor, std::string_view extra, std::string_view content) {
    text_ += "<text";
    attr("x", x);
    attr("y", y);
    text_ += " text-anchor=\"";
    text_ += anchor;
    text_ += '"';
    if (!extra.empty()) {
      text_ += ' ';
      text_ += extra;
    }
    text_ += '>';
    escaped(content);
    text_ += "</text>\n";
  }

  /// A triangle with its tip `length` metres ahead of `pose` and a base `width` metres across.
  void arrow(std::string_view cls, const hal::Pose2& pose, double length, double width, std::string_view style) {
    const double ahead_x = std::sin(pose.theta);
    const double ahead_y = std::cos(pose.theta);
    // Right of the heading in the world frame (the heading turns clockwise towards it).
    const double right_x = ahead_y;
    const double right_y = -ahead_x;
    const double back = -0.4 * length;
    text_ += "<polygon class=\"";
    text_ += cls;
    text_ += "\" points=\"";
    point(px(pose.x + length * 0.6 * ahead_x), py(pose.y + length * 0.6 * ahead_y));
    text_ += ' ';
    point(px(pose.x + back * ahead_x + 0.5 * width * right_x), py(pose.y + back * ahead_y + 0.5 * width * right_y));
    text_ += ' ';
    point(px(pose.x + back * ahead_x - 0.5 * width * right_x), py(pose.y + back * ahead_y - 0.5 * width * right_y));
    text_ += "\" ";
    text_ += style;
    text_ += "/>\n";
  }

  void cross_mark(std::string_view cls, double x_px, double y_px, double half) {
    text_ += "<path class=\"";
    text_ += cls;
    text_ += "\" d=\"M";
    point(x_px - half, y_px - half);
    text_ += " L";
    point(x_px + half, y_px + half);
    text_ += " M";
    point(x_px - half, y_px + half);
    text_ += " L";
    point(x_px + half, y_px - half);
    text_ += "\" stroke=\"";
    text_ += kCollisionStroke;
    text_ += "\" stroke-width=\"2.5\" stroke-linecap=\"round\" fill=\"none\"/>\n";
  }

  // --- the layers, bottom to top -------------------------------------------------------------------

  void ground() {
    // A field with painted lines reads as grass; a plain world stays white.
    const std::string_view fill = world_.markings.empty() && world_.rings.empty() ? "fill=\"#ffffff\"" : "fill=\"#6aa84f\"";
    rect("ground", px(world_.min.x), py(world_.max.y), world_px_width(), world_px_height(), fill);
    rect("walls", px(world_.min.x), py(world_.max.y), world_px_width(), world_px_height(),
         "fill=\"none\" stroke=\"#8a8a8a\" stroke-width=\"6\"");
  }

  void markings() {
    for (const Marking& m : world_.markings) {
      std::string style = "stroke=\"#ffffff\" stroke-linecap=\"square\" stroke-width=\"";
      detail::append_fixed(style, std::max(1.0, m.width * scale_), 3);
      style += '"';
      line("marking", px(m.a.x), py(m.a.y), px(m.b.x), py(m.b.y), style);
    }
    for (const Ring& r : world_.rings) {
      std::string style = "fill=\"none\" stroke=\"#ffffff\" stroke-width=\"";
      detail::append_fixed(style, std::max(1.0, r.width * scale_), 3);
      style += '"';
      circle("marking", px(r.centre.x), py(r.centre.y), r.radius * scale_, style);
    }
  }

  void obstacles() {
    const std::string fill = std::string("fill=\"") + kObstacleFill + '"';
    for (const Circle& c : world_.circles) circle("obstacle", px(c.centre.x), py(c.centre.y), c.radius * scale_, fill);
    for (const Polygon& polygon : world_.polygons) {
      text_ += "<polygon class=\"obstacle\" points=\"";
      for (std::size_t i = 0; i < polygon.vertices.size(); ++i) {
        if (i > 0) text_ += ' ';
        point(px(polygon.vertices[i].x), py(polygon.vertices[i].y));
      }
      text_ += "\" ";
      text_ += fill;
      text_ += "/>\n";
    }
  }

  void ball() {
    if (!world_.ball) return;
    // At true scale a 5 cm ball is a speck; keep it visible.
    const double r = std::max(4.0, world_.ball->radius * scale_);
    circle("ball", px(world_.ball->position.x), py(world_.ball->position.y), r,
           "fill=\"#ff8c1a\" stroke=\"#8a4500\" stroke-width=\"1\"");
  }

  // The planner's map: its region grid (faint lines) and every cell it marked occupied.
  void plan_map() {
    const hal::PlanPicture& m = overlay_.plans;
    if (!(m.cell > 0.0) || m.width_cells <= 0 || m.height_cells <= 0) return;
    const double region = m.cell * std::max(m.region_cells, 1);
    const double x0 = m.origin.x, y0 = m.origin.y;
    const double x1 = x0 + m.cell * m.width_cells, y1 = y0 + m.cell * m.height_cells;
    const std::string_view grid = "stroke=\"#ffffff\" stroke-opacity=\"0.35\" stroke-width=\"0.6\"";
    for (int i = 0; i * region <= x1 - x0 + 1e-9; ++i) line("region-grid", px(x0 + i * region), py(y0), px(x0 + i * region), py(y1), grid);
    for (int j = 0; j * region <= y1 - y0 + 1e-9; ++j) line("region-grid", px(x0), py(y0 + j * region), px(x1), py(y0 + j * region), grid);
    const double side = m.cell * scale_;
    const std::string style = std::string("fill=\"") + kOccupiedFill + "\" fill-opacity=\"0.85\"";
    for (const std::uint32_t c : m.occupied) {
      const double cx = x0 + (c % static_cast<std::uint32_t>(m.width_cells)) * m.cell;
      const double cy = y0 + (c / static_cast<std::uint32_t>(m.width_cells)) * m.cell;
      rect("occupied", px(cx), py(cy + m.cell), side, side, style);
    }
  }

  // A task planner's places: small rings named by their objects.
  void places() {
    const std::string style = std::string("fill=\"none\" stroke=\"") + kPlaceColour + "\" stroke-width=\"1.5\"";
    for (const hal::NamedPoint& p : overlay_.plans.places) {
      circle("place", px(p.at.x), py(p.at.y), 5.0, style);
      label(px(p.at.x) + 7.0, py(p.at.y) - 7.0, "start", "class=\"place\" font-size=\"11\" fill=\"#5a5a5a\"", p.name);
    }
  }

  // Where the controller told its planner of an obstacle: a yellow diamond with an edge.
  void reported_mark(std::string_view cls, double x, double y) {
    text_ += "<polygon class=\"";
    text_ += cls;
    text_ += "\" points=\"";
    point(x, y - 8.0);
    text_ += ' ';
    point(x + 8.0, y);
    text_ += ' ';
    point(x, y + 8.0);
    text_ += ' ';
    point(x - 8.0, y);
    text_ += "\" fill=\"";
    text_ += kReportedFill;
    text_ += "\" stroke=\"#222222\" stroke-width=\"1.2\"/>\n";
  }

  void reported() {
    for (const hal::WorldPoint& r : overlay_.plans.reported) reported_mark("reported", px(r.x), py(r.y));
  }

  [[nodiscard]] bool has_plan_row() const noexcept {
    return overlay_.plans.cell > 0.0 || !overlay_.plans.plan_ends.empty();
  }

  // The first plan solid, every later one (a replan, or the plan to the next goal) faded.
  void plans() {
    const hal::PlanPicture& m = overlay_.plans;
    std::size_t begin = 0;
    for (std::size_t i = 0; i < m.plan_ends.size(); ++i) {
      const std::size_t end = std::min<std::size_t>(m.plan_ends[i], m.plan_points.size());
      if (end > begin + 1) {
        text_ += "<polyline class=\"plan\" points=\"";
        for (std::size_t k = begin; k < end; ++k) {
          if (k > begin) text_ += ' ';
          point(px(m.plan_points[k].x), py(m.plan_points[k].y));
        }
        text_ += "\" fill=\"none\" stroke=\"";
        text_ += kPlanStroke;
        text_ += i == 0 ? "\" stroke-width=\"2.5\" stroke-opacity=\"0.95\"" : "\" stroke-width=\"1.5\" stroke-opacity=\"0.35\"";
        text_ += " stroke-dasharray=\"6 4\" stroke-linejoin=\"round\"/>\n";
      }
      begin = end;
    }
  }

  void trajectory() {
    if (overlay_.trajectory.empty()) return;
    text_ += "<polyline class=\"trajectory\" points=\"";
    for (std::size_t i = 0; i < overlay_.trajectory.size(); ++i) {
      if (i > 0) text_ += ' ';
      point(px(overlay_.trajectory[i].x), py(overlay_.trajectory[i].y));
    }
    text_ += "\" fill=\"none\" stroke=\"";
    text_ += kTrajectoryStroke;
    text_ += "\" stroke-width=\"2\" stroke-linejoin=\"round\" stroke-linecap=\"round\"/>\n";
  }

  [[nodiscard]] bool has_localization_row() const noexcept {
    return !overlay_.localization.truth.empty() || !overlay_.localization.snapshots.empty();
  }

  // The simulator's true path, dashed under the estimated one.
  void truth() {
    const std::span<const hal::Pose2> t = overlay_.localization.truth;
    if (t.empty()) return;
    text_ += "<polyline class=\"truth\" points=\"";
    for (std::size_t i = 0; i < t.size(); ++i) {
      if (i > 0) text_ += ' ';
      point(px(t[i].x), py(t[i].y));
    }
    text_ += "\" fill=\"none\" stroke=\"";
    text_ += kTruthStroke;
    text_ += "\" stroke-width=\"1.6\" stroke-dasharray=\"5 3\" stroke-linejoin=\"round\"/>\n";
  }

  // Each snapshot's particles: one path of short strokes from each particle along its heading.
  void particles() {
    const hal::LocalizationPicture& l = overlay_.localization;
    std::size_t begin = 0;
    for (const hal::LocalizationSnapshot& snap : l.snapshots) {
      const std::size_t end = std::min<std::size_t>(snap.particles_end, l.particles.size());
      if (end > begin) {
        text_ += "<path class=\"particles\" d=\"";
        for (std::size_t k = begin; k < end; ++k) {
          const hal::Pose2& p = l.particles[k];
          text_ += k > begin ? " M" : "M";
          point(px(p.x), py(p.y));
          text_ += " l";
          point(0.12 * scale_ * std::sin(p.theta), -0.12 * scale_ * std::cos(p.theta));
        }
        text_ += "\" fill=\"none\" stroke=\"";
        text_ += kParticleStroke;
        text_ += "\" stroke-width=\"1.4\" stroke-opacity=\"0.55\" stroke-linecap=\"round\"/>\n";
      }
      begin = end;
    }
  }

  // What each snapshot's correction weighed: the observed segments placed with the estimate, the
  // estimate itself and when (and why) the snapshot was taken.
  void observed() {
    const hal::LocalizationPicture& l = overlay_.localization;
    const std::string seg_style = std::string("stroke=\"") + kObservedStroke + "\" stroke-width=\"3\" stroke-linecap=\"round\"";
    const std::string arrow_style = std::string("fill=\"#ffffff\" stroke=\"") + kParticleStroke + "\" stroke-width=\"1.5\"";
    std::size_t begin = 0;
    for (const hal::LocalizationSnapshot& snap : l.snapshots) {
      const std::size_t end = std::min<std::size_t>(snap.segments_end, l.segments.size());
      for (std::size_t k = begin; k < end; ++k) {
        const hal::WorldSegment& g = l.segments[k];
        line("observed", px(g.a.x), py(g.a.y), px(g.b.x), py(g.b.y), seg_style);
      }
      begin = end;
      arrow("snapshot", snap.estimate, 0.3, 0.2, arrow_style);
      std::string text;
      detail::append_fixed(text, snap.time_s, 1);
      text += " s";
      if (snap.reason != "every 5 s" && !snap.reason.empty()) {
        text += ' ';
        text += snap.reason;
      }
      label(px(snap.estimate.x) + 9.0, py(snap.estimate.y) + 16.0, "start",
            "class=\"snapshot-time\" font-size=\"12\" font-weight=\"bold\" fill=\"#7a0f4c\" stroke=\"#ffffff\" stroke-width=\"3\" paint-order=\"stroke\"", text);
    }
  }

  void goals() {
    const double r = std::max(8.0, kGoalRadiusM * scale_);
    for (std::size_t i = 0; i < overlay_.goals.size(); ++i) {
      const bool reached = i < overlay_.goals_reached;
      const double cx = px(overlay_.goals[i].x);
      const double cy = py(overlay_.goals[i].y);
      std::string style = reached ? std::string("fill=\"") + kGoalColour + '"' : std::string("fill=\"#ffffff\"");
      style += std::string(" stroke=\"") + kGoalColour + "\" stroke-width=\"2\"";
      circle(reached ? "goal reached" : "goal", cx, cy, r, style);
      label(cx, cy + 4.5, "middle", reached ? "fill=\"#ffffff\" font-weight=\"bold\"" : "font-weight=\"bold\"",
            std::to_string(i + 1));
    }
  }

  void start_pose() {
    arrow("start", world_.start, 0.8, 0.5,
          std::string("fill=\"") + kStartFill + "\" stroke=\"#ffffff\" stroke-width=\"1\"");
  }

  void collisions() {
    for (const hal::WorldPoint& c : overlay_.collisions) cross_mark("collision", px(c.x), py(c.y), 6.0);
  }

  void footer() {
    const double top = kMarginPx + world_px_height();
    const double left = kMarginPx;
    label(left, top + 26.0, "start", "class=\"caption\" font-size=\"15\"", overlay_.caption);

    // Scale bar: 1 m with end ticks.
    const double bar_y = top + 52.0;
    const std::string_view bar_style = "stroke=\"#222222\" stroke-width=\"2\"";
    line("scale-bar", left, bar_y, left + scale_, bar_y, bar_style);
    line("scale-bar", left, bar_y - 5.0, left, bar_y + 5.0, bar_style);
    line("scale-bar", left + scale_, bar_y - 5.0, left + scale_, bar_y + 5.0, bar_style);
    label(left + scale_ + 8.0, bar_y + 4.5, "start", "", "1 m");

    // Legend: one row of swatches with their meaning.
    const double y = top + 82.0;
    double x = left + 8.0;
    const double step = 140.0;
    line("legend", x - 8.0, y, x + 8.0, y,
         std::string("stroke=\"") + kTrajectoryStroke + "\" stroke-width=\"2\"");
    label(x + 14.0, y + 4.5, "start", "", has_localization_row() ? "estimated trajectory" : "trajectory");
    x += has_localization_row() ? 1.3 * step : step;
    text_ += "<polygon class=\"legend\" points=\"";
    point(x, y - 7.0);
    text_ += ' ';
    point(x + 6.0, y + 6.0);
    text_ += ' ';
    point(x - 6.0, y + 6.0);
    text_ += "\" fill=\"";
    text_ += kStartFill;
    text_ += "\"/>\n";
    label(x + 14.0, y + 4.5, "start", "", "start pose");
    x += step;
    circle("legend", x, y, 7.0, std::string("fill=\"") + kGoalColour + '"');
    label(x + 14.0, y + 4.5, "start", "", "goal reached");
    x += step;
    circle("legend", x, y, 7.0, std::string("fill=\"#ffffff\" stroke=\"") + kGoalColour + "\" stroke-width=\"2\"");
    label(x + 14.0, y + 4.5, "start", "", "goal pending");
    x += step;
    rect("legend", x - 7.0, y - 7.0, 14.0, 14.0, std::string("fill=\"") + kObstacleFill + '"');
    label(x + 14.0, y + 4.5, "start", "", "obstacle");
    x += step;
    cross_mark("legend", x, y, 6.0);
    label(x + 14.0, y + 4.5, "start", "", "collision");
    if (has_localization_row()) {  // a row for the localization (the last one)
      const double y3 = y + (has_plan_row() ? 48.0 : 24.0);
      double x3 = left + 8.0;
      line("legend", x3 - 8.0, y3, x3 + 8.0, y3,
           std::string("stroke=\"") + kTruthStroke + "\" stroke-width=\"1.6\" stroke-dasharray=\"5 3\"");
      label(x3 + 14.0, y3 + 4.5, "start", "", "true trajectory (simulator)");
      x3 += 1.6 * step;
      line("legend", x3 - 6.0, y3 + 3.0, x3 + 6.0, y3 - 3.0,
           std::string("stroke=\"") + kParticleStroke + "\" stroke-width=\"1.4\" stroke-linecap=\"round\"");
      label(x3 + 14.0, y3 + 4.5, "start", "", "particles at a snapshot (time, why)");
      x3 += 1.9 * step;
      line("legend", x3 - 8.0, y3, x3 + 8.0, y3,
           std::string("stroke=\"") + kObservedStroke + "\" stroke-width=\"3\" stroke-linecap=\"round\"");
      label(x3 + 14.0, y3 + 4.5, "start", "", "lines seen then, placed by the estimate");
    }
    if (has_plan_row()) {  // a second row: the planner's picture
      const double y2 = y + 24.0;
      double x2 = left + 8.0;
      line("legend", x2 - 8.0, y2, x2 + 8.0, y2,
           std::string("stroke=\"") + kPlanStroke + "\" stroke-width=\"2.5\" stroke-dasharray=\"6 4\"");
      label(x2 + 14.0, y2 + 4.5, "start", "", "first plan (later plans faded)");
      x2 += 2.0 * step;
      if (overlay_.plans.cell > 0.0) {
        rect("legend", x2 - 5.0, y2 - 5.0, 10.0, 10.0, std::string("fill=\"") + kOccupiedFill + '"');
        label(x2 + 14.0, y2 + 4.5, "start", "", "occupied cell (planner's map; grid: regions)");
        x2 += 2.5 * step;
      }
      if (!overlay_.plans.places.empty()) {
        circle("legend", x2, y2, 5.0, std::string("fill=\"none\" stroke=\"") + kPlaceColour + "\" stroke-width=\"1.5\"");
        label(x2 + 14.0, y2 + 4.5, "start", "", "place (PDDL object)");
        x2 += 1.5 * step;
      }
      if (!overlay_.plans.reported.empty()) {
        reported_mark("legend", x2, y2);
        label(x2 + 14.0, y2 + 4.5, "start", "", "obstacle reported to the planner");
      }
    }
  }

  const World& world_;
  const hal::RunPicture& overlay_;
  double scale_;  // pixels per metre
  std::string text_;
};

}  // namespace

void write_world_svg(std::ostream& out, const World& world, const hal::RunPicture& overlay) {
  out << SvgPicture(world, overlay).draw();
}

void write_world_svg(const std::filesystem::path& path, const World& world, const hal::RunPicture& overlay) {
  const std::string picture = SvgPicture(world, overlay).draw();
  const auto fail = [&path](int error) {
    const std::string reason = error != 0 ? std::generic_category().message(error) : "I/O error";
    throw std::runtime_error(path.string() + ": cannot write SVG: " + reason);
  };
  errno = 0;
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  if (!file) fail(errno);
  file.write(picture.data(), static_cast<std::streamsize>(picture.size()));
  file.flush();
  if (!file) fail(errno);
}

}  // namespace ringlet::sim_hal
