// NAO robots: tall non-field columns standing on the field, verified by HOG + SVM (robots.hpp).
#include "ringlet/vision/robots.hpp"

#include <algorithm>
#include <cmath>

#include "ringlet/hal/portable_math.hpp"
#include "ringlet/vision/bw_ball.hpp"  // svm_confidence

namespace ringlet::vision {

WindowPlacement robot_window(const RobotParams& p, const HogParams& hog, const hal::Pixel& foot,
                             double height_px) noexcept {
  const double win_h = p.window_height * height_px;
  const double scale = win_h / static_cast<double>(hog.window_height);
  const double win_w = scale * static_cast<double>(hog.window_width);
  return {foot.u - 0.5 * win_w, foot.v - p.foot_row * win_h, scale};
}

double RobotDetector::expected_height_px(const hal::CameraIntrinsics& k, const hal::CameraPose& pose,
                                         const hal::RobotPoint& g) const noexcept {
  const auto foot = hal::project(k, pose, {g.x, g.y, 0.0});
  const auto head = hal::project(k, pose, {g.x, g.y, params_.height_m});
  if (!foot || !head) return 0.0;
  return std::max(0.0, foot->v - head->v);
}

RobotBox robot_box(const RobotCandidate& c, int step, const RobotParams& params) noexcept {
  RobotBox b;
  b.foot = {0.5 * (c.x_min + c.x_max + step), static_cast<double>(c.foot_row)};
  b.height = c.height_px;
  b.width = c.height_px * params.width_m / params.height_m;
  b.left = b.foot.u - 0.5 * b.width;
  b.top = c.foot_row - c.height_px;
  return b;
}

void RobotDetector::detect(const ClassImage& classes, const hal::FrameView& frame, const hal::CameraIntrinsics& k,
                           const hal::CameraPose& pose, int stride, HogClassifier* classifier, int max_verified,
                           const Deadline& deadline, RobotList& out) noexcept {
  propose(classes, k, pose, stride, out);
  report(frame, k, pose, classifier, max_verified, max_verified, deadline, out);
}

void RobotDetector::propose(const ClassImage& classes, const hal::CameraIntrinsics& k, const hal::CameraPose& pose,
                            int stride, RobotList& out) noexcept {
  out = RobotList{};
  count_ = 0;
  const int s = classes.step();
  step_ = s;
  const int col_stride = std::max(s, (std::max(stride, 1) + s - 1) / s * s);
  const int first = classes.first_row();
  const int h = classes.height();
  int columns_seen = 0;  // scan columns with an entry in column_foot_
  const auto height_at = [&](double u, double v) {
    const auto p = hal::pixel_to_ground(k, pose, {u, v});
    return p ? expected_height_px(k, pose, *p) : 0.0;
  };

  // A candidate goes into the fixed list; when it is full, the farthest gives way.
  const auto nearer = [](const Candidate& a, const Candidate& b) {
    if (a.pieces != b.pieces) return !a.pieces;
    return a.foot_row != b.foot_row ? a.foot_row > b.foot_row : a.x_max - a.x_min > b.x_max - b.x_min;
  };
  const auto push = [&](const Candidate& c) {
    if (count_ < cands_.size()) {
      cands_[count_++] = c;
      return;
    }
    // With "nearer" as the order's "less", the greatest element is the farthest.
    auto farthest = std::max_element(cands_.begin(), cands_.end(), nearer);
    if (nearer(c, *farthest)) *farthest = c;
  };
  // Ends a candidate: collected with its expected height; the width is judged after the pieces of
  // one robot have been put together (below).
  raw_count_ = 0;
  const auto finish = [&](Candidate c) {
    c.height_px = height_at(0.5 * (c.x_min + c.x_max + s), c.foot_row);
    if (c.height_px <= 0.0) return;
    if (raw_count_ < raw_.size()) raw_[raw_count_++] = c;
  };
  // The open candidate, and the columns beside it whose runs end higher up (a shadow): the field
  // between its legs when the open one goes on after them, else something farther away of its own.
  Candidate open{};
  bool has_open = false;
  Candidate shadow{};
  bool has_shadow = false;
  int join = 0;  // columns at most this far from the open candidate's right edge may still join it
  int last_foot = 0;  // the foot row of the open candidate's last column
  const auto join_for = [&](double eh) {  // eh: the expected height at the candidate's foot
    return std::max(2 * col_stride, static_cast<int>(params_.join_share * eh * params_.width_m / params_.height_m));
  };
  const auto start = [&](int x, int foot, double eh) {
    open = {x, x, foot, 1, 0.0};
    has_open = true;
    last_foot = foot;
    join = join_for(eh);
  };
  const auto close = [&]() {  // the open candidate ends; its shadow, if any, takes its place
    if (!has_open) return;
    finish(open);
    has_open = false;
    if (has_shadow) {
      has_shadow = false;
      open = shadow;
      has_open = true;
      last_foot = shadow.foot_row;
      join = join_for(height_at(shadow.x_max + 0.5 * s, shadow.foot_row));
    }
  };

  for (int x = 0; x < classes.width(); x += col_stride) {
    // The longest qualifying run of this column that stands on the field (the lowest one wins ties).
    // A robot's body is not uniformly non-field (shaded grey parts can pass for carpet): field
    // gaps shorter than max_gap_share of the expected height do not end a run.
    int best_foot = -1;
    int run_start = -1;
    int field_since = -1;  // first field row after the current run (-1: inside the run)
    double run_eh = 0.0;   // the expected height at field_since (computed once per gap)
    int gap_at = -1;       // the last bridged gap inside the run: where it began ...
    int gap_end = -1;      // ... and where non-field resumed
    for (int y = first; y <= h; y += s) {
      const bool nf = y < h && classes.at(x, y) != ColourClass::kField;
      if (nf) {
        if (run_start < 0) run_start = y;
        if (field_since >= 0) {
          gap_at = field_since;
          gap_end = y;
        }
        field_since = -1;
        continue;
      }
      if (run_start < 0) continue;
      if (field_since < 0) {
        field_since = y;
        run_eh = height_at(x + 0.5 * s, field_since);  // the run's foot row
      }
      if (y < h && y - field_since < std::max(2 * s, static_cast<int>(params_.max_gap_share * run_eh))) continue;
      // What followed the last bridged gap must be longer than twice the gap to belong to the
      // robot (its legs below a shaded part); shorter, it lies before the feet (the ball).
      // A run that reaches the image's bottom edge has its feet at the edge or below it: the
      // last row is its foot (the distance an upper bound). Its last bridged gap is a shaded
      // part of the legs, not the feet: taking it put near robots' feet 40-80 px too high.
      const bool feet_out_of_view = field_since >= h;
      int foot = feet_out_of_view ? h - 1 : field_since;
      if (!feet_out_of_view && gap_at >= 0 && field_since - gap_end < 2 * (gap_end - gap_at)) {
        foot = gap_at;
        run_eh = height_at(x + 0.5 * s, foot);
      }
      if (foot < h && run_eh >= params_.min_height_px &&
          (foot - run_start >= params_.min_height_share * run_eh || run_start == first)) {
        best_foot = foot;
      }
      run_start = -1;
      field_since = -1;
      gap_at = -1;
      gap_end = -1;
    }
    if (x / col_stride < static_cast<int>(column_foot_.size())) {
      column_foot_[static_cast<std::size_t>(x / col_stride)] = best_foot;
      columns_seen = x / col_stride + 1;
    }
    // The open candidate (and a shadow promoted in its place) out of reach ends.
    while (has_open && x - open.x_max > join) close();
    if (best_foot < 0) continue;
    const double eh = height_at(x + 0.5 * s, best_foot);
    const int tolerance = std::max(2 * s, static_cast<int>(params_.foot_tolerance_share * eh));
    if (has_open && std::abs(best_foot - last_foot) <= tolerance) {
      open.x_max = x;
      open.foot_row = std::max(open.foot_row, best_foot);
      ++open.columns;
      last_foot = best_foot;
      has_shadow = false;  // it was the field between the legs
      continue;
    }
    if (has_open && best_foot < open.foot_row) {
      if (has_shadow && x - shadow.x_max <= 2 * col_stride && std::abs(best_foot - shadow.foot_row) <= tolerance) {
        shadow.x_max = x;
        shadow.foot_row = std::max(shadow.foot_row, best_foot);
        ++shadow.columns;
      } else {
        if (has_shadow) finish(shadow);
        shadow = {x, x, best_foot, 1, 0.0};
        has_shadow = true;
      }
      continue;
    }
    // Lower (nearer) than the open candidate, or nothing open: a new candidate starts.
    if (has_open) {
      finish(open);
      has_open = false;
    }
    if (has_shadow) finish(shadow);
    has_shadow = false;
    start(x, best_foot, eh);
  }
  while (has_open) close();
  // Pieces of one robot: something nearer standing before it (a ball, a line seen through its legs)
  // cuts its columns into pieces, each too narrow for a robot. Pieces whose foot rows agree and
  // which together are no wider than a robot are put together (left to right; a narrow piece
  // takes part in every merge, so two whole robots side by side stay apart).
  for (std::size_t i = 1; i < raw_count_; ++i) {  // left to right (insertion sort: no allocation)
    const Candidate c = raw_[i];
    std::size_t j = i;
    for (; j > 0 && raw_[j - 1].x_min > c.x_min; --j) raw_[j] = raw_[j - 1];
    raw_[j] = c;
  }
  const auto width_of = [&](const Candidate& c) { return static_cast<double>(c.x_max - c.x_min + s); };
  const auto expected_width_of = [&](const Candidate& c) { return robot_box(c, s, params_).width; };
  const auto narrow = [&](const Candidate& c) { return width_of(c) < params_.min_width_share * expected_width_of(c); };
  for (std::size_t i = 0; i < raw_count_; ++i) {
    for (std::size_t j = i + 1; j < raw_count_;) {
      Candidate& a = raw_[i];
      const Candidate& b = raw_[j];
      const Candidate& nearer_one = a.foot_row >= b.foot_row ? a : b;
      const double eh = nearer_one.height_px;
      const int tolerance = std::max(2 * s, static_cast<int>(params_.foot_tolerance_share * eh));
      Candidate m = a;
      m.x_min = std::min(a.x_min, b.x_min);
      m.x_max = std::max(a.x_max, b.x_max);
      m.foot_row = std::max(a.foot_row, b.foot_row);
      m.columns = a.columns + b.columns;
      m.pieces = true;
      if (narrow(a) && narrow(b) && std::abs(a.foot_row - b.foot_row) <= tolerance &&
          width_of(m) <= params_.merge_width_share * expected_width_of(nearer_one)) {
        m.height_px = height_at(0.5 * (m.x_min + m.x_max + s), m.foot_row);
        if (m.height_px > 0.0) {
          a = m;
          for (std::size_t q = j + 1; q < raw_count_; ++q) raw_[q - 1] = raw_[q];
          --raw_count_;
          j = i + 1;  // the merged candidate may now reach another piece
          continue;
        }
      }
      ++j;
    }
  }
  // Robots standing before the field's edge (robots.hpp): inside a wide candidate, the columns
  // whose feet lie clearly below the edge interpolated from either side. True when any was found.
  const auto split_at_edge = [&](const Candidate& c) {
    const int i0 = c.x_min / col_stride;
    const int i1 = c.x_max / col_stride;
    if (i1 >= columns_seen) return false;
    const double expected_width = expected_width_of(c);
    const int reach = std::max(2, static_cast<int>(0.75 * expected_width / col_stride));
    const int gap = std::max(1, static_cast<int>(params_.join_share * expected_width / col_stride));
    const int rise = std::max(2 * s, static_cast<int>(params_.protrusion_share * c.height_px));
    const auto foot_at = [&](int i) { return column_foot_[static_cast<std::size_t>(i)]; };
    // The nearest column with a foot from `i` towards `toward` (-1: none before it).
    const auto valid_from = [&](int i, int toward) {
      const int dir = toward > i ? 1 : -1;
      for (; i != toward; i += dir) {
        if (foot_at(i) >= 0) return i;
      }
      return -1;
    };
    bool found = false;
    Candidate part{};
    bool open_part = false;
    int last = 0;
    const auto end_part = [&]() {
      if (!open_part) return;
      open_part = false;
      part.height_px = height_at(0.5 * (part.x_min + part.x_max + s), part.foot_row);
      if (part.height_px <= 0.0 || width_of(part) < params_.min_width_share * expected_width_of(part)) return;
      push(part);
      found = true;
    };
    for (int i = i0; i <= i1; ++i) {
      const int f = foot_at(i);
      if (f < 0) continue;
      // The edge through a column on either side, or, near the candidate's end, through two on
      // the one side (a sloping edge is not flat).
      int l = i - reach >= i0 ? valid_from(i - reach, i) : -1;
      int r = i + reach <= i1 ? valid_from(i + reach, i) : -1;
      if (l < 0 && r >= 0) l = r + reach <= i1 ? valid_from(r + reach, r) : -1;
      if (r < 0 && l >= 0) r = l - reach >= i0 ? valid_from(l - reach, l) : -1;
      if (l < 0 || r < 0 || l == r) continue;
      const double t = static_cast<double>(i - l) / static_cast<double>(r - l);
      const double edge = foot_at(l) + t * (foot_at(r) - foot_at(l));
      if (f - edge < rise) continue;
      const int x = i * col_stride;
      if (open_part && i - last <= gap) {
        part.x_max = x;
        part.foot_row = std::max(part.foot_row, f);
        ++part.columns;
      } else {
        end_part();
        part = {x, x, f, 1, 0.0};
        open_part = true;
      }
      last = i;
    }
    end_part();
    return found;
  };
  // Kept when about a robot wide at its foot.
  for (std::size_t i = 0; i < raw_count_; ++i) {
    const Candidate& c = raw_[i];
    const double width = width_of(c);
    const double expected_width = expected_width_of(c);
    if (width > params_.split_width_share * expected_width && split_at_edge(c)) continue;
    if (width < params_.min_width_share * expected_width || width > params_.max_width_share * expected_width) continue;
    push(c);
  }
  out.candidates = static_cast<int>(count_);
  // Nearest first: the lowest foot row, then the wider (insertion sort: stable, no allocation). The
  // nearest obstacles matter most, and a near robot fills its window best.
  for (std::size_t i = 1; i < count_; ++i) {
    const Candidate c = cands_[i];
    std::size_t j = i;
    for (; j > 0 && nearer(c, cands_[j - 1]); --j) cands_[j] = cands_[j - 1];
    cands_[j] = c;
  }
}

void RobotDetector::report(const hal::FrameView& frame, const hal::CameraIntrinsics& k, const hal::CameraPose& pose,
                           HogClassifier* classifier, int max_verified, int windows_allowed, const Deadline& deadline,
                           RobotList& out) noexcept {
  const int s = step_;
  const bool use_classifier = classifier != nullptr && max_verified > 0;
  const std::size_t n = use_classifier ? std::min(count_, static_cast<std::size_t>(max_verified)) : count_;
  for (std::size_t i = 0; i < n && out.count < kMaxRobots; ++i) {
    const Candidate& c = cands_[i];
    RobotDetection r;
    const RobotBox box = robot_box(c, s, params_);
    const auto ground = hal::pixel_to_ground(k, pose, box.foot);  // finish() kept only feet on the ground
    if (!ground) continue;
    r.ground = *ground;
    const double eh = box.height;
    const double near = hal::portable_hypot(r.ground.x, r.ground.y);
    if (near > 0.0) {
      const double k_far = 1.0 + params_.foot_depth_m / near;
      r.ground = {r.ground.x * k_far, r.ground.y * k_far};
    }
    r.foot = box.foot;
    r.height = box.height;
    r.width = box.width;
    r.left = box.left;
    r.top = box.top;
    r.distance_m = hal::portable_hypot(r.ground.x, r.ground.y);
    r.bearing_rad = std::atan2(r.ground.y, r.ground.x);
    if (use_classifier) {
      if (deadline.expired() || out.classified >= windows_allowed) {
        out.classifications_cut = static_cast<int>(n - i);
        break;
      }
      const WindowPlacement w = robot_window(params_, classifier->model().params(), r.foot, eh);
      r.score = classifier->score_window(frame, w.left, w.top, w.scale);
      ++out.classified;
      if (r.score < classifier->model().threshold()) continue;
      r.verified = true;
      r.confidence = svm_confidence(r.score, classifier->model().threshold());
    } else {
      const double width = c.x_max - c.x_min + s;
      r.confidence = 0.3 * std::min(1.0, width / std::max(r.width, 1.0));
    }
    out.robots[out.count++] = r;
  }
}

}  // namespace ringlet::vision
