#include "report.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "ringlet/vision/stages.hpp"
#include "vision_io.hpp"

namespace ringlet::vision::evaluate {

namespace {

std::string fmt(const char* format, double v) {
  char text[64];
  std::snprintf(text, sizeof text, format, v);
  return text;
}

// "0-3", "3-4", ..., ">=5": a kRingDistanceBinsM bin.
std::string distance_bin_name(std::size_t b) {
  if (b + 1 >= kRingDistanceBinsM.size()) return ">=" + fmt("%g", kRingDistanceBinsM[b]);
  return fmt("%g", kRingDistanceBinsM[b]) + "-" + fmt("%g", kRingDistanceBinsM[b + 1]);
}

std::string xml_escape(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '&': out += "&amp;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

// Every matched expected robot, worst distance error first: which robots make the maximum.
nlohmann::json robot_matches_json(std::vector<EvalReport::RobotMatchInFrame> matches) {
  std::stable_sort(matches.begin(), matches.end(),
                   [](const auto& a, const auto& b) { return a.match.relative_error > b.match.relative_error; });
  nlohmann::json out = nlohmann::json::array();
  for (const auto& [frame, m] : matches) {
    out.push_back({{"frame", frame}, {"true_distance_m", m.true_distance_m}, {"found_distance_m", m.found_distance_m},
                   {"relative_error", m.relative_error}, {"foot_offset_px", m.foot_offset_px},
                   {"matched_by", m.by_foot ? "foot point" : "box overlap"}});
  }
  return out;
}

// Recall by the paint's width in the picture (segment_match.hpp's buckets).
nlohmann::json recall_by_width_json(const MatchCounts& c) {
  nlohmann::json out = nlohmann::json::array();
  for (std::size_t b = 0; b < kWidthBucketsPx.size(); ++b) {
    const std::size_t n = c.truths_by_width[b];
    nlohmann::json row = {{"min_px", kWidthBucketsPx[b]}, {"truths", n}, {"recalled", c.recalled_by_width[b]},
                          {"recall", n == 0 ? 0.0 : static_cast<double>(c.recalled_by_width[b]) / static_cast<double>(n)}};
    row["max_px"] = b + 1 < kWidthBucketsPx.size() ? nlohmann::json(kWidthBucketsPx[b + 1]) : nlohmann::json(nullptr);
    out.push_back(std::move(row));
  }
  return out;
}

nlohmann::json detector_json(const DetectorReport& d) {
  const MatchCounts& c = d.counts;
  // Per test frame, in the order of "test_frames": [truths, recalled, detections, true positives].
  nlohmann::json per_frame = nlohmann::json::array();
  for (const MatchCounts& f : d.per_frame) per_frame.push_back({f.truths, f.recalled, f.detections, f.true_positives});
  // The reported segments per test frame, [x0, y0, x1, y1] in pixels (to draw or re-score).
  nlohmann::json segments = nlohmann::json::array();
  for (const auto& frame : d.segments) {
    nlohmann::json here = nlohmann::json::array();
    for (const Segment2& s : frame) here.push_back({s.x0, s.y0, s.x1, s.y1});
    segments.push_back(std::move(here));
  }
  return {{"name", d.name},
          {"per_frame_lines", per_frame},
          {"per_frame_segments", segments},
          {"precision", c.precision()},
          {"recall", c.recall()},
          {"f1", c.f1()},
          {"detections_scored", c.detections},
          {"detections_all", d.raw_detections},
          {"true_positives", c.true_positives},
          {"truths", c.truths},
          {"recalled", c.recalled},
          {"mean_angle_error_deg", c.mean_angle_error_deg()},
          {"mean_endpoint_error_px", c.mean_endpoint_error_px()},
          {"mean_extent_error_px", c.mean_extent_error_px()},
          {"recall_by_width", recall_by_width_json(c)},
          {"arc_false_positives", d.arc_false_positives()},
          {"frames_with_arc_false_positives", d.frames_with_arc_false_positives()},
          {"per_frame_arc_pieces", d.per_frame_arcs},
          {"time_ms", {{"median", d.median_ms()}, {"p99", d.p99_ms()}, {"mean", d.mean_ms()}, {"per_frame", d.time_ms}}}};
}

nlohmann::json object_json(const ObjectCounts& c, const char* error_name) {
  return {{"precision", c.precision()},
          {"recall", c.recall()},
          {"f1", c.f1()},
          {"detections", c.detections},
          {"true_positives", c.true_positives},
          {"expected", c.expected},
          {"recalled", c.recalled},
          {error_name, {{"mean", c.mean_error()}, {"max", c.error_max}, {"count", c.errors}}}};
}

void print_objects(const EvalReport& r, std::ostream& os) {
  if (r.object_frames == 0) {
    os << "\nballs and robots: not scored (no frame carries balls[] and robots[] truth: generator version < 3)\n";
    return;
  }
  const BallMatchParams& bm = r.ball_match;
  const RobotMatchParams& rm = r.robot_match;
  os << "\nball (" << r.ball_mode << ", model " << r.ball_model << ") on " << r.object_frames
     << " frames: a match is a centre within max(" << bm.centre_share << " x radius, " << bm.min_centre_px
     << " px); expected within " << bm.max_distance_m << " m and >= " << bm.min_visible * 100.0 << " % visible\n";
  const auto print = [&](const ObjectCounts& c, const char* error) {
    os << "  expected " << c.expected << ", recalled " << c.recalled << ", detections " << c.detections << " ("
       << c.true_positives << " right)\n";
    os << "  precision " << fmt("%.3f", c.precision()) << "  recall " << fmt("%.3f", c.recall()) << "  F1 "
       << fmt("%.3f", c.f1()) << "  " << error << " mean " << fmt("%.1f", 100.0 * c.mean_error()) << " %  max "
       << fmt("%.1f", 100.0 * c.error_max) << " % (" << c.errors << ")\n";
  };
  print(r.balls, "relative distance error");
  if (r.ball_mode == "bw") {
    os << "  proposed: " << r.ball_proposals.recalled << " of the " << r.ball_proposals.expected
       << " expected balls have a candidate (" << fmt("%.3f", r.ball_proposals.recall())
       << ": the most the classifier could recall)\n";
  }
  os << "robots (model " << r.robot_model << "): a match is a foot point within max(" << rm.foot_share
     << " x box width, " << rm.min_foot_px << " px) or box IoU >= " << rm.min_iou << "; expected within "
     << rm.max_distance_m << " m, foot in the image, >= " << rm.min_visible * 100.0 << " % visible\n";
  print(r.robots, "relative foot distance error");
  os << "  proposed: " << r.robot_proposals.recalled << " of the " << r.robot_proposals.expected
     << " expected robots have a candidate (" << fmt("%.3f", r.robot_proposals.recall())
     << ": the most the classifier could recall)\n";
}

}  // namespace

void print_report(const EvalReport& r, std::ostream& os) {
  os << "test set:   " << r.test_set << "\n";
  os << "tuning set: " << (r.tuning_set.empty() ? "none (Hough with OpenCV-style defaults)" : r.tuning_set) << "\n";
  for (const std::string& e : r.excluded_sets) os << "excluded:   " << e << "\n";
  os << "checked:    " << r.disjointness << "\n";
  if (r.tune_frames > 0) {
    os << "Hough tuned on the " << r.tune_frames << " tuning frames (best F1 of " << r.tuning.size()
       << " parameter sets); both detectors reported on the " << r.report_frames << " test frames only\n";
  } else {
    os << "Hough untuned (defaults), both detectors reported on the " << r.report_frames << " test frames\n";
  }
  os << "colour table: " << r.lut << "\n";
  os << "RANSAC seed:  " << r.ransac_seed << "\n";
  if (r.pitch_error_deg != 0.0 || r.auto_pitch) {
    os << "head pitch:   each frame's " << (r.pitch_error_deg >= 0.0 ? "+ " : "- ") << std::abs(r.pitch_error_deg) << " deg";
    if (r.auto_pitch) {
      os << ", corrected from the lines (--auto-pitch) in " << r.pitch_corrected << " of " << r.report_frames
         << " frames, |error| after: median " << percentile(r.pitch_abs_error_deg, 50.0) << ", p90 "
         << percentile(r.pitch_abs_error_deg, 90.0) << " deg; median correction "
         << percentile(r.pitch_correction_deg, 50.0) << " deg (the camera's pitch as mounted, over the set)";
    }
    os << "\n";
  }
  os << "Hough parameters: " << r.hough.describe() << "\n";
  os << "matching: angle <= " << r.match.max_angle_deg << " deg, endpoints <= " << r.match.max_distance_px
     << " px + half line width, recall needs coverage >= " << r.match.min_coverage << ", truths shorter than "
     << r.match.min_truth_length_px << " px ignored\n\n";
  char line[256];
  std::snprintf(line, sizeof line, "%-28s %14s %14s\n", "", "Ringlet", "Canny+HoughP");
  os << line;
  const auto row = [&](const char* name, const std::string& a, const std::string& b) {
    std::snprintf(line, sizeof line, "%-28s %14s %14s\n", name, a.c_str(), b.c_str());
    os << line;
  };
  const MatchCounts& a = r.ringlet.counts;
  const MatchCounts& b = r.baseline.counts;
  row("precision", fmt("%.3f", a.precision()), fmt("%.3f", b.precision()));
  row("recall", fmt("%.3f", a.recall()), fmt("%.3f", b.recall()));
  row("F1", fmt("%.3f", a.f1()), fmt("%.3f", b.f1()));
  row("detections (scored)", std::to_string(a.detections), std::to_string(b.detections));
  row("true segments (recalled)", std::to_string(a.truths) + " (" + std::to_string(a.recalled) + ")",
      std::to_string(b.truths) + " (" + std::to_string(b.recalled) + ")");
  row("mean angle error (deg)", fmt("%.2f", a.mean_angle_error_deg()), fmt("%.2f", b.mean_angle_error_deg()));
  row("mean endpoint error (px)", fmt("%.2f", a.mean_endpoint_error_px()), fmt("%.2f", b.mean_endpoint_error_px()));
  row("mean extent error (px)", fmt("%.1f", a.mean_extent_error_px()), fmt("%.1f", b.mean_extent_error_px()));
  for (std::size_t k = 0; k < kWidthBucketsPx.size(); ++k) {
    const std::string name = k + 1 < kWidthBucketsPx.size()
                                 ? "recall, paint " + fmt("%.0f", kWidthBucketsPx[k]) + "-" + fmt("%.0f", kWidthBucketsPx[k + 1]) + " px"
                                 : "recall, paint >= " + fmt("%.0f", kWidthBucketsPx[k]) + " px";
    const auto cell = [&](const MatchCounts& m) {
      return m.truths_by_width[k] == 0 ? std::string("-")
                                       : fmt("%.3f", static_cast<double>(m.recalled_by_width[k]) /
                                                         static_cast<double>(m.truths_by_width[k])) +
                                             " (" + std::to_string(m.truths_by_width[k]) + ")";
    };
    row(name.c_str(), cell(a), cell(b));
  }
  row("time/frame median (ms)", fmt("%.3f", r.ringlet.median_ms()), fmt("%.3f", r.baseline.median_ms()));
  row("time/frame p99 (ms)", fmt("%.3f", r.ringlet.p99_ms()), fmt("%.3f", r.baseline.p99_ms()));
  row("arc pieces taken for lines", std::to_string(r.ringlet.arc_false_positives()),
      std::to_string(r.baseline.arc_false_positives()));
  row("  frames with any", std::to_string(r.ringlet.frames_with_arc_false_positives()),
      std::to_string(r.baseline.frames_with_arc_false_positives()));
  row("  with the circle missed", std::to_string(r.arc_frames_circle_missed), "-");
  os << "speed ratio (Hough median / Ringlet median): " << fmt("%.2f", r.speed_ratio()) << "x\n";
  os << "cost model on this host (modelled_cost / board factor): median " << fmt("%.3f", percentile(r.model_host_ms, 50.0))
     << " ms; measured / modelled per frame: median " << fmt("%.2f", r.measured_over_modelled(50.0)) << ", p90 "
     << fmt("%.2f", r.measured_over_modelled(90.0)) << "\n";
  os << "  by stage, median measured / modelled ms:";
  for (std::size_t s = 0; s < kStageCount; ++s) {
    const auto& t = r.stage_times[s];
    os << " " << stage_name(static_cast<Stage>(s)) << " " << fmt("%.3f", percentile(t.measured_ms, 50.0)) << "/"
       << fmt("%.3f", percentile(t.modelled_ms, 50.0));
  }
  os << "\n";
  const CircleCounts& c = r.circle;
  os << "\ncentre circle (Ringlet): a match is a centre within " << r.circle_match.max_centre_error_m
     << " m and a radius within " << r.circle_match.max_radius_error_m << " m of the truth; expected when >= "
     << r.circle_match.min_visible_deg << " deg of it is visible\n";
  os << "  frames showing some of it " << r.rings_visible << ", expected " << c.truths << ", recalled " << c.recalled
     << ", detections " << c.detections << " (" << c.true_positives << " right)\n";
  os << "  precision " << fmt("%.3f", c.precision()) << "  recall " << fmt("%.3f", c.recall()) << "  F1 "
     << fmt("%.3f", c.f1()) << "  mean centre error " << fmt("%.3f", c.mean_centre_error_m()) << " m  mean radius error "
     << fmt("%.3f", c.mean_radius_error_m()) << " m\n";
  os << "  recall by the circle's distance:";
  for (std::size_t bin = 0; bin < kRingDistanceBinsM.size(); ++bin) {
    os << "  " << distance_bin_name(bin) << " m " << c.recalled_by_distance[bin] << "/" << c.truths_by_distance[bin];
  }
  os << "\n";
  const CircleCounts& m = r.marks;
  os << "\npenalty and centre marks (Ringlet): a match is a centre within " << r.mark_match.max_centre_error_m
     << " m of a cross's; expected when a bar is >= " << r.mark_match.min_bar_px
     << " px long in the picture (the bars also count as line detections above)\n";
  os << "  expected " << m.truths << ", recalled " << m.recalled << ", detections " << m.detections << " ("
     << m.true_positives << " right)  precision " << fmt("%.3f", m.precision()) << "  recall "
     << fmt("%.3f", m.recall()) << "  mean centre error " << fmt("%.3f", m.mean_centre_error_m()) << " m\n";
  print_objects(r, os);
}

namespace {
/// Per stage: the medians of its measured time and of the model's rows for it.
nlohmann::json stage_json(const EvalReport& r) {
  nlohmann::json out = nlohmann::json::object();
  for (std::size_t s = 0; s < kStageCount; ++s) {
    const auto& t = r.stage_times[s];
    out[std::string(stage_name(static_cast<Stage>(s)))] = {{"measured_median_ms", percentile(t.measured_ms, 50.0)},
                                 {"modelled_median_ms", percentile(t.modelled_ms, 50.0)}};
  }
  return out;
}

// The centre circle's and the marks' common figures (both CircleCounts).
nlohmann::json landmark_json(const CircleCounts& c) {
  return {{"precision", c.precision()},          {"recall", c.recall()},
          {"f1", c.f1()},                        {"detections_scored", c.detections},
          {"true_positives", c.true_positives},  {"expected", c.truths},
          {"recalled", c.recalled},              {"mean_centre_error_m", c.mean_centre_error_m()}};
}
}  // namespace

nlohmann::json report_json(const EvalReport& r) {
  nlohmann::json circle = landmark_json(r.circle);
  circle["frames_showing_some"] = r.rings_visible;
  circle["frames_with_arc_pieces_circle_missed"] = r.arc_frames_circle_missed;
  nlohmann::json by_distance = nlohmann::json::array();
  for (std::size_t b = 0; b < kRingDistanceBinsM.size(); ++b) {
    nlohmann::json bin = {{"from_m", kRingDistanceBinsM[b]},
                          {"expected", r.circle.truths_by_distance[b]},
                          {"recalled", r.circle.recalled_by_distance[b]}};
    bin["to_m"] = b + 1 < kRingDistanceBinsM.size() ? nlohmann::json(kRingDistanceBinsM[b + 1]) : nlohmann::json(nullptr);
    by_distance.push_back(bin);
  }
  circle["recall_by_distance"] = by_distance;
  circle["mean_radius_error_m"] = r.circle.mean_radius_error_m();
  circle["match"] = {{"max_centre_error_m", r.circle_match.max_centre_error_m},
                     {"max_radius_error_m", r.circle_match.max_radius_error_m},
                     {"min_visible_deg", r.circle_match.min_visible_deg}};
  nlohmann::json marks = landmark_json(r.marks);
  marks["bars_scored_as_lines"] = true;
  marks["match"] = {{"max_centre_error_m", r.mark_match.max_centre_error_m}, {"min_bar_px", r.mark_match.min_bar_px}};
  nlohmann::json tuning = nlohmann::json::array();
  for (const TuningResult& t : r.tuning) {
    tuning.push_back({{"params", t.params.describe()}, {"f1", t.counts.f1()}, {"precision", t.counts.precision()},
                      {"recall", t.counts.recall()}});
  }
  return {{"dataset", r.dataset},
          {"colour_table", r.lut},
          {"ransac_seed", r.ransac_seed},
          {"pitch", {{"error_deg", r.pitch_error_deg},
                     {"auto_pitch", r.auto_pitch},
                     {"corrected_frames", r.pitch_corrected},
                     {"median_correction_deg", percentile(r.pitch_correction_deg, 50.0)},
                     {"abs_error_after_deg", {{"median", percentile(r.pitch_abs_error_deg, 50.0)},
                                              {"p90", percentile(r.pitch_abs_error_deg, 90.0)}}}}},
          {"test_set", r.test_set},
          {"tuning_set", r.tuning_set},
          {"excluded_sets", r.excluded_sets},
          {"disjointness", r.disjointness},
          {"frames_total", r.frames_total},
          {"tune_frames", r.tune_frames},
          {"report_frames", r.report_frames},
          {"test_frames", r.test_frames},
          {"protocol", "Hough parameters chosen by best F1 on the tuning set; both detectors scored on the test set "
                       "only, which was checked to share no frame (seed and index, or pixels) with the tuning set "
                       "and the excluded sets; each detector timed alone with steady_clock, one thread"},
          {"match", {{"max_angle_deg", r.match.max_angle_deg}, {"max_distance_px", r.match.max_distance_px},
                     {"min_coverage", r.match.min_coverage}, {"min_truth_length_px", r.match.min_truth_length_px}}},
          {"hough_params", r.hough.describe()},
          {"hough_tuning", tuning},
          {"detectors", {{"ringlet", detector_json(r.ringlet)}, {"hough", detector_json(r.baseline)}}},
          {"speed_ratio", r.speed_ratio()},
          {"cost_model", {{"modelled_host_median_ms", percentile(r.model_host_ms, 50.0)},
                          {"measured_over_modelled", {{"median", r.measured_over_modelled(50.0)},
                                                      {"p90", r.measured_over_modelled(90.0)},
                                                      {"max", r.measured_over_modelled(100.0)}}},
                          {"stages", stage_json(r)}}},
          {"object_frames", r.object_frames},
          {"ball_mode", r.ball_mode},
          {"ball_model", r.ball_model},
          {"robot_model", r.robot_model},
          {"balls", object_json(r.balls, "distance_error")},
          {"ball_proposals", {{"expected", r.ball_proposals.expected}, {"recalled", r.ball_proposals.recalled},
                              {"recall", r.ball_proposals.recall()}, {"candidates", r.ball_proposals.detections}}},
          {"robots", object_json(r.robots, "foot_distance_error")},
          {"robot_matches", robot_matches_json(r.robot_matches)},
          {"robot_proposals", {{"expected", r.robot_proposals.expected}, {"recalled", r.robot_proposals.recalled},
                               {"recall", r.robot_proposals.recall()}, {"candidates", r.robot_proposals.detections}}},
          {"ball_match", {{"centre_share", r.ball_match.centre_share}, {"min_centre_px", r.ball_match.min_centre_px},
                          {"max_distance_m", r.ball_match.max_distance_m}, {"min_visible", r.ball_match.min_visible}}},
          {"robot_match", {{"foot_share", r.robot_match.foot_share}, {"min_foot_px", r.robot_match.min_foot_px},
                           {"min_iou", r.robot_match.min_iou}, {"max_distance_m", r.robot_match.max_distance_m},
                           {"min_visible", r.robot_match.min_visible}}},
          {"circle", circle},
          {"marks", marks}};
}

std::string report_svg(const EvalReport& r) {
  // Left panel: P, R, F1 bars per detector. Right panel: per-frame time, a strip of dots per
  // detector on a log axis with median and p99 ticks (times differ by orders of magnitude).
  constexpr int kW = 860, kH = 400;
  const std::array<const char*, 2> colour{"#2e7d32", "#1565c0"};
  const std::array<const DetectorReport*, 2> det{&r.ringlet, &r.baseline};
  const std::array<const char*, 2> label{"Ringlet", "Canny+HoughLinesP"};
  std::ostringstream s;
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << kW << "\" height=\"" << kH
    << "\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  s << "<text x=\"10\" y=\"20\" font-size=\"14\" font-weight=\"bold\">Field lines: Ringlet vs Canny + HoughLinesP, "
    << r.report_frames << " unseen test frames (Hough tuned on " << r.tune_frames << " other frames)</text>\n";
  s << "<text x=\"10\" y=\"38\" font-size=\"10\" fill=\"#555\">test set " << xml_escape(r.test_set) << "</text>\n";
  // Panel 1.
  const int x0 = 50, y0 = 60, ph = 260, pw = 330;
  s << "<line x1=\"" << x0 << "\" y1=\"" << y0 + ph << "\" x2=\"" << x0 + pw << "\" y2=\"" << y0 + ph
    << "\" stroke=\"black\"/>\n<line x1=\"" << x0 << "\" y1=\"" << y0 << "\" x2=\"" << x0 << "\" y2=\"" << y0 + ph
    << "\" stroke=\"black\"/>\n";
  for (int t = 0; t <= 4; ++t) {
    const int y = y0 + ph - t * ph / 4;
    s << "<text x=\"" << x0 - 8 << "\" y=\"" << y + 4 << "\" text-anchor=\"end\">" << fmt("%.2f", t / 4.0)
      << "</text><line x1=\"" << x0 << "\" y1=\"" << y << "\" x2=\"" << x0 + pw << "\" y2=\"" << y
      << "\" stroke=\"#ddd\"/>\n";
  }
  const std::array<const char*, 3> metric{"precision", "recall", "F1"};
  for (std::size_t m = 0; m < 3; ++m) {
    const int gx = x0 + 20 + static_cast<int>(m) * 105;
    for (std::size_t d = 0; d < 2; ++d) {
      const MatchCounts& c = det[d]->counts;
      const double v = m == 0 ? c.precision() : (m == 1 ? c.recall() : c.f1());
      const int h = static_cast<int>(std::lround(v * ph));
      const int x = gx + static_cast<int>(d) * 40;
      s << "<rect x=\"" << x << "\" y=\"" << y0 + ph - h << "\" width=\"36\" height=\"" << h << "\" fill=\""
        << colour[d] << "\"/><text x=\"" << x + 18 << "\" y=\"" << y0 + ph - h - 4 << "\" text-anchor=\"middle\">"
        << fmt("%.2f", v) << "</text>\n";
    }
    s << "<text x=\"" << gx + 38 << "\" y=\"" << y0 + ph + 18 << "\" text-anchor=\"middle\">" << metric[m] << "</text>\n";
  }
  // Panel 2: log10 time axis.
  const int x1 = 480, pw2 = 340;
  double lo = 1e9, hi = 0.0;
  for (const auto* d : det) {
    for (const double t : d->time_ms) {
      lo = std::min(lo, t);
      hi = std::max(hi, t);
    }
  }
  if (!(hi > 0.0)) {
    lo = 0.1;
    hi = 10.0;
  }
  const double l0 = std::floor(std::log10(std::max(lo, 1e-3)));
  const double l1 = std::max(std::ceil(std::log10(hi)), l0 + 1.0);
  const auto xt = [&](double ms) {
    return x1 + static_cast<int>(std::lround((std::log10(std::max(ms, 1e-3)) - l0) / (l1 - l0) * pw2));
  };
  s << "<text x=\"" << x1 << "\" y=\"" << y0 - 10 << "\">time per frame (ms, log scale)</text>\n";
  s << "<line x1=\"" << x1 << "\" y1=\"" << y0 + ph << "\" x2=\"" << x1 + pw2 << "\" y2=\"" << y0 + ph
    << "\" stroke=\"black\"/>\n";
  for (double e = l0; e <= l1 + 1e-9; e += 1.0) {
    const double ms = std::pow(10.0, e);
    const int x = xt(ms);
    s << "<line x1=\"" << x << "\" y1=\"" << y0 << "\" x2=\"" << x << "\" y2=\"" << y0 + ph
      << "\" stroke=\"#ddd\"/><text x=\"" << x << "\" y=\"" << y0 + ph + 18 << "\" text-anchor=\"middle\">"
      << fmt("%g", ms) << "</text>\n";
  }
  for (std::size_t d = 0; d < 2; ++d) {
    const int yc = y0 + 70 + static_cast<int>(d) * 120;
    s << "<text x=\"" << x1 << "\" y=\"" << yc - 38 << "\" fill=\"" << colour[d] << "\">" << label[d] << ": median "
      << fmt("%.3f", det[d]->median_ms()) << " ms, p99 " << fmt("%.3f", det[d]->p99_ms()) << " ms</text>\n";
    std::size_t k = 0;
    for (const double t : det[d]->time_ms) {
      const int jitter = static_cast<int>((k++ * 7919U) % 41U) - 20;  // deterministic spread
      s << "<circle cx=\"" << xt(t) << "\" cy=\"" << yc + jitter << "\" r=\"1.6\" fill=\"" << colour[d]
        << "\" fill-opacity=\"0.45\"/>\n";
    }
    s << "<line x1=\"" << xt(det[d]->median_ms()) << "\" y1=\"" << yc - 28 << "\" x2=\"" << xt(det[d]->median_ms())
      << "\" y2=\"" << yc + 28 << "\" stroke=\"black\" stroke-width=\"2\"/>\n";
    s << "<line x1=\"" << xt(det[d]->p99_ms()) << "\" y1=\"" << yc - 28 << "\" x2=\"" << xt(det[d]->p99_ms())
      << "\" y2=\"" << yc + 28 << "\" stroke=\"black\" stroke-dasharray=\"4 3\"/>\n";
  }
  s << "<text x=\"10\" y=\"" << kH - 12 << "\">" << "Legend: <tspan fill=\"" << colour[0] << "\">■ Ringlet</tspan>  <tspan fill=\""
    << colour[1] << "\">■ Canny+HoughLinesP</tspan>; speed ratio (median) " << fmt("%.1f", r.speed_ratio())
    << "x; solid tick median, dashed p99</text>\n";
  s << "</svg>\n";
  return s.str();
}

}  // namespace ringlet::vision::evaluate
