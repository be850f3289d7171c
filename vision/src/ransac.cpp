// RANSAC line extraction on the ground. Order of one extraction round:
//   trials (deadline checked before each) → best hypothesis → inliers → TLS refit → inliers again
//   → arc test (centre circle) → split at gaps → segments; then the round's inliers leave the pool.
// After all rounds collinear segments are merged.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include "ringlet/hal/portable_math.hpp"
#include "ringlet/vision/prng.hpp"
#include "ringlet/vision/ransac.hpp"

namespace ringlet::vision {
namespace {

// Cuts a reported segment's ends back to where the picture shows paint (LineCheck's painted span),
// keeping its line; the image ends follow.
void trim_to_paint(FieldLine& f, const hal::CameraIntrinsics& k, const hal::CameraPose& pose,
                   const LineCheck::Span& span) noexcept {
  if (span.from <= 0.0 && span.to >= 1.0) return;
  const hal::RobotPoint a = f.ground_start, b = f.ground_end;
  const auto at = [&](double t) { return hal::RobotPoint{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)}; };
  f.ground_start = at(span.from);
  f.ground_end = at(span.to);
  f.length_m *= span.to - span.from;
  if (const auto p0 = hal::project(k, pose, {f.ground_start.x, f.ground_start.y, 0.0})) f.image_start = *p0;
  if (const auto p1 = hal::project(k, pose, {f.ground_end.x, f.ground_end.y, 0.0})) f.image_end = *p1;
}

double norm(double x, double y) noexcept { return hal::portable_hypot(x, y); }

bool on_circle(const CentreCircle& c, const hal::RobotPoint& q, double band) noexcept {
  return std::abs(norm(q.x - c.centre.x, q.y - c.centre.y) - c.radius_m) <= band;
}

// Removes the reported lines `drop` picks (drop_lines); how many went, for the stats.
template <class Drop>
int drop_reported(LineSet& out, const Drop& drop) noexcept {
  const std::size_t before = out.count;
  out.count = drop_lines(out.lines, out.count, drop);
  return static_cast<int>(before - out.count);
}

}  // namespace

RansacScratch::RansacScratch(std::size_t capacity) : arc_scratch_(capacity) {
  points_.reserve(capacity);
  pixels_.reserve(capacity);
  along_.reserve(capacity);
  across_.reserve(capacity);
  pool_.reserve(capacity);
  sample_.reserve(capacity);
  inliers_.reserve(capacity);
  circle_members_.reserve(capacity);
  arc_.reserve(capacity);
  piece_.reserve(capacity);
  order_.reserve(capacity);
}

double RansacLineFinder::tan_deg(double deg) noexcept { return std::tan(deg * std::numbers::pi / 180.0); }

template <class Direction>
RansacLineFinder::SquaredOffsets RansacLineFinder::squared_offsets(std::span<const int> members,
                                                                  const Direction& direction) const noexcept {
  SquaredOffsets acc;
  for (const int p : members) {
    if (!has_direction(p)) continue;
    const auto h = direction(scratch_.points_[static_cast<std::size_t>(p)]);
    if (!h) continue;
    const PaintOffset o = paint_offset(h->x, h->y, p);
    const double t = o.off / std::max(o.on, 1e-12);
    acc.sum += t * t;
    ++acc.n;
  }
  return acc;
}

double RansacLineFinder::paint_rms(double dx, double dy, std::span<const int> members) const noexcept {
  const SquaredOffsets a = squared_offsets(members, [&](const hal::RobotPoint&) {
    return std::optional<hal::RobotPoint>{{dx, dy}};
  });
  return a.n == 0 ? std::numeric_limits<double>::infinity() : std::sqrt(a.sum / static_cast<double>(a.n));
}

double RansacLineFinder::tangent_rms(const CentreCircle& c, std::span<const int> members) const noexcept {
  const SquaredOffsets a = squared_offsets(members, [&](const hal::RobotPoint& q) -> std::optional<hal::RobotPoint> {
    const double dx = q.x - c.centre.x, dy = q.y - c.centre.y;
    const double r = norm(dx, dy);
    if (r <= 0.0) return std::nullopt;
    return hal::RobotPoint{-dy / r, dx / r};  // the tangent there
  });
  return a.n == 0 ? 0.0 : std::sqrt(a.sum / static_cast<double>(a.n));
}

void RansacLineFinder::remove_from_pool(std::span<const int> members) noexcept {
  // members are sorted ascending (they are collected by walking the pool, which stays sorted).
  auto& pool = scratch_.pool_;
  pool.erase(std::remove_if(pool.begin(), pool.end(),
                            [&](int i) { return std::binary_search(members.begin(), members.end(), i); }),
             pool.end());
}

void RansacLineFinder::find(std::span<const CandidatePoint> candidates, std::uint64_t frame, const hal::CameraIntrinsics& k,
                            const hal::CameraPose& pose, const Deadline& deadline, LineSet& out, int max_trials,
                            int max_lines, int skip_override, int scan_stride, const CentreCircle* circle,
                            const LineCheck* check, std::int64_t max_point_tests) noexcept {
  out.count = 0;
  out.circle = circle != nullptr && circle->seen ? *circle : CentreCircle{};
  out.stats = RansacStats{};
  RansacStats& st = out.stats;
  auto& s = scratch_;
  s.points_.clear();
  s.pixels_.clear();
  s.along_.clear();
  s.across_.clear();
  s.pool_.clear();
  const auto skip = static_cast<std::size_t>(std::max(skip_override >= 1 ? skip_override : params_.skip, 1));
  for (std::size_t i = 0; i < candidates.size() && s.points_.size() < s.points_.capacity(); ++i) {
    const hal::RobotPoint& q = candidates[i].ground;
    // Points of the known circle take no part: no line can be fitted through its arcs. A line
    // crossing it (the halfway line) only loses the few centimetres where it crosses the band.
    if (out.circle.seen && on_circle(out.circle, q, tolerance(q))) {
      ++st.circle_points;
      continue;
    }
    s.pool_.push_back(static_cast<int>(s.points_.size()));
    s.points_.push_back(q);
    s.pixels_.push_back(candidates[i].pixel);
    s.along_.push_back(candidates[i].ground_along);
    s.across_.push_back(candidates[i].ground_across);
  }
  st.points_in = static_cast<int>(candidates.size());
  const int trials = max_trials >= 0 ? max_trials : params_.max_trials;
  const int rounds_cap = std::clamp(max_lines >= 0 ? max_lines : params_.max_lines, 0, static_cast<int>(kMaxLines));
  const auto min_inliers = static_cast<std::size_t>(std::max(params_.min_inliers, 2));
  const auto min_sampled = static_cast<std::size_t>(std::max(params_.min_sampled_inliers, 2));
  SplitMix64 rng = SplitMix64::for_frame(params_.seed, frame);
  // A point belongs to a line when it lies in its band and its paint runs along it (or its
  // direction is unknown).
  const auto fits = [&](const Line2& l, int p) { return in_band(l, p) && along_paint(l, p, max_direction_tan_); };

  int rounds = 0;
  int empty_rounds = 0;
  while (rounds < rounds_cap && s.pool_.size() >= min_inliers) {
    // RANSAC_SKIP: this round's trials see every skip-th unassigned point only.
    // Never thinner than min_sample_points: once the long lines are out, the short ones left
    // need their points in the sample to be found at all.
    const std::size_t step = std::max<std::size_t>(
        1, std::min(skip, s.pool_.size() / static_cast<std::size_t>(std::max(params_.min_sample_points, 1))));
    s.sample_.clear();
    for (std::size_t i = 0; i < s.pool_.size(); i += step) s.sample_.push_back(s.pool_[i]);
    if (rounds == 0) st.points_used = static_cast<int>(s.sample_.size());
    if (s.sample_.size() < min_sampled) break;
    std::size_t best = 0;
    Line2 best_line;
    int t = 0;
    for (; t < trials; ++t) {
      // The point tests as the cost model counts them: the first round's sample per trial, and
      // every draw of a second point. A trial starts only if it fits with one draw, and draws no
      // more than fit.
      const auto tests_with_another_draw = [&] {
        return static_cast<std::int64_t>(st.trials_run) * st.points_used + st.partner_draws + 1;
      };
      if (deadline.expired() || tests_with_another_draw() + st.points_used > max_point_tests) {
        st.stopped_early = true;
        break;
      }
      ++st.trials_run;
      const std::size_t n = s.sample_.size();
      const auto i = static_cast<std::size_t>(rng.below(n));
      const int ia = s.sample_[i];
      const hal::RobotPoint a = s.points_[static_cast<std::size_t>(ia)];
      // The second point: where the first one's paint is known, one that lies along it and
      // whose own paint runs that way too (the pair's line passes both points' direction gates),
      // by up to kPartnerDraws draws. Drawn blindly, both points lie on a line holding a tenth of
      // the sample once in a hundred trials (30 trials find it one time in four); along the
      // paint, about as often for a short line as for a long one. Else the last draw.
      int ib = ia;
      const int draws = has_direction(ia) && max_direction_tan_ >= 0.0 ? kPartnerDraws : 1;
      for (int draw = 0; draw < draws && (draw == 0 || tests_with_another_draw() <= max_point_tests); ++draw) {
        auto j = static_cast<std::size_t>(rng.below(n - 1));
        if (j >= i) ++j;
        ib = s.sample_[j];
        ++st.partner_draws;
        const hal::RobotPoint& q = s.points_[static_cast<std::size_t>(ib)];
        const double hx = q.x - a.x, hy = q.y - a.y;
        if (along_paint(hx, hy, ia, max_direction_tan_) && along_paint(hx, hy, ib, max_direction_tan_)) break;
      }
      const hal::RobotPoint b = s.points_[static_cast<std::size_t>(ib)];
      const double len = norm(b.x - a.x, b.y - a.y);
      if (len < 1e-6) continue;
      const Line2 hypothesis{a, (b.x - a.x) / len, (b.y - a.y) / len};
      std::size_t count = 0;
      for (const int p : s.sample_) count += fits(hypothesis, p) ? 1U : 0U;
      if (count > best) {
        best = count;
        best_line = hypothesis;
      }
    }
    st.trials_skipped += trials - t;
    // A cut round still uses its best hypothesis so far: degrade, do not discard.
    if (best < min_sampled) break;

    const auto collect = [&](const Line2& l) {
      s.inliers_.clear();
      for (const int p : s.pool_) {
        if (fits(l, p)) s.inliers_.push_back(p);
      }
    };
    // From here on every candidate counts: the fit, the endpoints and the gaps are dense.
    collect(best_line);
    // Too few for a line: this round's draws found none (clutter won the sample: the floor beyond
    // the carpet, a robot), which says little of the short lines still in the pool. The round
    // counts and the next one draws again, until max_empty_rounds of them found nothing.
    if (s.inliers_.size() < min_inliers) {
      if (++empty_rounds >= params_.max_empty_rounds) break;
      ++rounds;
      continue;
    }
    Line2 line = best_line;
    if (const auto refined = fit_line_tls({s.points_, s.inliers_})) {
      line = *refined;
      collect(line);
      if (s.inliers_.size() < min_inliers) {  // the refit drifted off: keep the hypothesis
        line = best_line;
        collect(line);
      }
    }
    ++rounds;
    if (add_pieces(line, k, pose, std::max(scan_stride, 1), check, out)) ++st.lines_extracted;
    remove_from_pool(s.inliers_);
    if (st.stopped_early) break;
  }
  if (st.stopped_early) st.points_left = static_cast<int>(s.pool_.size());
  drop_on_circle(out);
  merge(out, k, pose, check);
  drop_cut_short(out, k);
  drop_beyond_field(out);
}

void RansacLineFinder::drop_beyond_field(LineSet& out) const noexcept {
  if (params_.max_range_m <= 0.0) return;
  out.stats.beyond_field += drop_reported(out, [&](const FieldLine& f) {
    return std::min(norm(f.ground_start.x, f.ground_start.y), norm(f.ground_end.x, f.ground_end.y)) > params_.max_range_m;
  });
}

void RansacLineFinder::drop_on_circle(LineSet& out) const noexcept {
  // A circle the rounds find themselves comes after the pieces earlier rounds reported; the arcs
  // among those go now. A piece lies on it when its ends, its middle and its quarter points all
  // do (the test a piece's points get against a known circle); a line crossing it does not.
  if (!out.circle.seen) return;
  out.stats.arcs_rejected += drop_reported(out, [&](const FieldLine& f) {
    for (int q = 0; q <= 4; ++q) {
      const double t = q / 4.0;
      const hal::RobotPoint p{f.ground_start.x + t * (f.ground_end.x - f.ground_start.x),
                              f.ground_start.y + t * (f.ground_end.y - f.ground_start.y)};
      if (!on_circle(out.circle, p, 2.0 * tolerance(p))) return false;
    }
    return true;
  });
}

void RansacLineFinder::drop_cut_short(LineSet& out, const hal::CameraIntrinsics& k) const noexcept {
  // A piece of a far circle mostly outside the picture is a few pixels of arc at its edge, too
  // short to bend visibly; a line leaving the picture looks the same there. With the circle
  // known its pieces are gone by now (drop_on_circle), so what is cut short then is a line's end.
  if (out.circle.seen || params_.min_cut_piece_px <= 0.0) return;
  const auto at_edge = [&](const hal::Pixel& p) {
    return p.u <= kEdgeMarginPx || p.v <= kEdgeMarginPx || p.u >= k.width - kEdgeMarginPx ||
           p.v >= k.height - kEdgeMarginPx;
  };
  out.stats.cut_short += drop_reported(out, [&](const FieldLine& f) {
    return (at_edge(f.image_start) || at_edge(f.image_end)) &&
           norm(f.image_end.u - f.image_start.u, f.image_end.v - f.image_start.v) < params_.min_cut_piece_px;
  });
}

bool RansacLineFinder::try_circle(const Line2& line, std::span<const int> piece, LineSet& out) noexcept {
  auto& s = scratch_;
  if (piece.size() < 6) return false;
  const IndexedPoints pts{s.points_, piece};
  double t_min = 1e300, t_max = -1e300;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const double t = line.along(pts[i]);
    t_min = std::min(t_min, t);
    t_max = std::max(t_max, t);
  }
  if (t_max - t_min > params_.circle_max_chord_m) return false;
  const CircleParams& cp = params_.circle;
  const double r0 = cp.radius_m;
  const double r_tol = cp.radius_tolerance * r0;
  ++out.stats.arcs_rejected;  // undone below when the piece is no arc

  // 1. Part of the circle already known: most of its points lie near it.
  if (out.circle.seen) {
    std::size_t near = 0;
    for (std::size_t i = 0; i < pts.size(); ++i) near += on_circle(out.circle, pts[i], 2.0 * tolerance(pts[i])) ? 1U : 0U;
    if (static_cast<double>(near) >= params_.arc_near_share * static_cast<double>(pts.size())) return true;
  }

  // 2. The bend test: the piece bends away from its own chord like the circle (more than half its
  // curvature 1/(2 r0), less than twice it), significantly. Catches short arcs whose line-fit
  // RMS is still small, and arcs whose Kåsa radius noise throws out of range.
  std::optional<Circle2> circle;
  const auto chord = fit_line_tls(pts);
  const auto bend = chord ? fit_bend(*chord, pts, cp.noise_floor_m) : std::nullopt;
  const double c0 = 1.0 / (2.0 * r0);
  if (bend && std::abs(bend->c) > c0 / 2.0 && std::abs(bend->c) < 2.0 * c0 && bend->z() >= params_.arc_min_bend_z) {
    // The circle's centre: r0 from the arc's middle, on the side it bends towards.
    const hal::RobotPoint mid = chord->at(bend->t_mid);
    const double side = bend->c > 0.0 ? 1.0 : -1.0;
    const double off = bend->a + side * r0;
    circle = Circle2{{mid.x - chord->dy * off, mid.y + chord->dx * off}, r0};
  }

  // 3. The Kåsa test: a circle fits much better than the line, with a radius near r0. Stray
  // points that merely lie in the line's band are trimmed first (a quarter of the piece at most):
  // the worst circle residual is dropped while it exceeds half the inlier tolerance.
  if (!circle) {
    s.arc_.assign(piece.begin(), piece.end());
    std::optional<Circle2> kasa;
    const std::size_t max_drops = piece.size() / 4;
    for (std::size_t drops = 0;; ++drops) {
      kasa = fit_circle({s.points_, s.arc_});
      if (!kasa) break;
      std::size_t worst = 0;
      double worst_excess = 0.0;
      for (std::size_t i = 0; i < s.arc_.size(); ++i) {
        const hal::RobotPoint& q = s.points_[static_cast<std::size_t>(s.arc_[i])];
        const double excess =
            std::abs(norm(q.x - kasa->centre.x, q.y - kasa->centre.y) - kasa->radius) - tolerance(q) / 2.0;
        if (excess > worst_excess) {
          worst_excess = excess;
          worst = i;
        }
      }
      if (worst_excess <= 0.0) break;
      if (drops == max_drops || s.arc_.size() <= 6) {
        kasa.reset();
        break;
      }
      s.arc_.erase(s.arc_.begin() + static_cast<std::ptrdiff_t>(worst));
    }
    if (kasa && std::abs(kasa->radius - r0) <= r_tol) {
      const IndexedPoints arc{s.points_, s.arc_};
      const auto arc_line = fit_line_tls(arc);
      const double lrms = arc_line ? line_rms(*arc_line, arc) : 0.0;
      if (lrms >= params_.circle_min_line_rms_m && circle_rms(*kasa, arc) < params_.circle_rms_ratio * lrms) circle = kasa;
    }
  }
  if (out.circle.seen) {
    if (circle) return true;  // an arc, but of no better circle than the known one
    --out.stats.arcs_rejected;
    return false;
  }
  // Refits c on the members `gather` collects until they stop growing, then judges it; a circle
  // that passes is the frame's, and its members leave the pool.
  const auto refine_and_judge = [&](Circle2 c, const auto& gather, bool tangent_members) {
    gather(c);
    for (int iteration = 0; iteration < 3; ++iteration) {
      const std::size_t before = s.circle_members_.size();
      const auto all = refine_centre_circle(c, s.points_, s.circle_members_, cp, s.arc_scratch_);
      if (!all) break;
      c = *all;
      gather(c);
      if (s.circle_members_.size() <= before) break;
    }
    return CentreCircleFinder::judge(c, s.points_, s.circle_members_, cp, s.arc_scratch_, tangent_members);
  };
  const auto accept = [&](const CentreCircle& judged) {
    out.circle = judged;
    remove_from_pool(s.circle_members_);
  };
  if (circle) {
    // An arc and no circle yet: every remaining point on that circle, and the piece's own.
    s.arc_.assign(piece.begin(), piece.end());
    std::sort(s.arc_.begin(), s.arc_.end());
    const auto gather = [&](const Circle2& c) {
      s.circle_members_.clear();
      for (const int p : s.pool_) {
        const hal::RobotPoint& q = s.points_[static_cast<std::size_t>(p)];
        const bool near = std::abs(norm(q.x - c.centre.x, q.y - c.centre.y) - c.radius) <= tolerance(q);
        if (near || std::binary_search(s.arc_.begin(), s.arc_.end(), p)) s.circle_members_.push_back(p);
      }
    };
    if (const CentreCircle judged = refine_and_judge(*circle, gather, false); judged.seen) {
      accept(judged);
      return true;
    }
    // It bends like an arc of a circle the frame does not show. Its paint says which it is: along
    // an arc it turns with the tangent, along a line bent by a few stray points (a goal post's
    // foot, a robot's) it keeps the line's direction.
    const CentreCircle arc{.seen = true, .centre = circle->centre, .radius_m = circle->radius};
    if (paint_rms(line.dx, line.dy, piece) * params_.arc_line_direction_ratio < tangent_rms(arc, piece)) {
      --out.stats.arcs_rejected;
      return false;
    }
    return true;
  }
  // No bend shows: a short piece of a far circle looks straight. It is an arc only if the circle
  // it touches (r0 to either side of its middle) is there: points in its band whose paint runs
  // along its tangent, over enough of its arc to pass the judgement. Their paint must follow the
  // tangent as closely as directions are measured: the lines of a corner that a circle nestles
  // in pass the gate only with their paint up to its limit.
  const hal::RobotPoint middle = line.at((t_min + t_max) / 2.0);
  if (t_max - t_min <= params_.tangent_circle_max_m && norm(middle.x, middle.y) >= params_.tangent_circle_min_range_m) {
    const auto tangent_gather = [&](const Circle2& c) {
      s.circle_members_.clear();
      for (const int p : s.pool_) {
        const hal::RobotPoint& q = s.points_[static_cast<std::size_t>(p)];
        const double dx = q.x - c.centre.x, dy = q.y - c.centre.y;
        const double r = norm(dx, dy);
        if (std::abs(r - c.radius) > tolerance(q) || r <= 0.0 || !has_direction(p)) continue;
        if (along_paint(Line2{q, -dy / r, dx / r}, p, max_direction_tan_)) s.circle_members_.push_back(p);
      }
    };
    for (const double side : {1.0, -1.0}) {
      const Circle2 touching{{middle.x - line.dy * side * r0, middle.y + line.dx * side * r0}, r0};
      const CentreCircle judged = refine_and_judge(touching, tangent_gather, true);
      if (judged.seen && tangent_rms(judged, s.circle_members_) <= max_tangent_rms_tan_) {
        accept(judged);
        return true;
      }
    }
  }
  --out.stats.arcs_rejected;
  return false;
}

double RansacLineFinder::min_support(const Line2& line, double t0, double t1, const LineCheck* check) const noexcept {
  if (check == nullptr) return params_.min_support;
  const double width = 2.0 * check->half_width_px(line.at((t0 + t1) / 2.0), line.dx, line.dy);
  return width > 0.0 && width < params_.thin_width_px ? params_.thin_min_support : params_.min_support;
}

bool RansacLineFinder::add_pieces(const Line2& line, const hal::CameraIntrinsics& k, const hal::CameraPose& pose,
                                  int scan_stride, const LineCheck* check, LineSet& out) noexcept {
  auto& s = scratch_;
  s.order_.clear();
  for (const int p : s.inliers_) s.order_.emplace_back(line.along(s.points_[static_cast<std::size_t>(p)]), p);
  std::sort(s.order_.begin(), s.order_.end());
  bool any = false;
  // [first, last]; `depth`: how many times this piece's points were split off a larger piece.
  const auto close_piece = [&](const auto& self, std::size_t first, std::size_t last, int depth) -> void {
    const auto count = static_cast<int>(last - first + 1);
    const double t0 = s.order_[first].first;
    const double t1 = s.order_[last].first;
    if (count < params_.min_inliers) return;
    // Arcs are tested per piece, so that a stray point far along the line cannot hide one.
    s.piece_.clear();
    for (std::size_t i = first; i <= last; ++i) s.piece_.push_back(s.order_[i].second);
    if (try_circle(line, s.piece_, out)) return;
    if (t1 - t0 < params_.min_length_m) return;
    if (out.count == kMaxLines) {
      ++out.stats.segments_dropped;
      return;
    }
    hal::RobotPoint g0 = line.at(t0);
    hal::RobotPoint g1 = line.at(t1);
    const auto p0 = hal::project(k, pose, {g0.x, g0.y, 0.0});
    const auto p1 = hal::project(k, pose, {g1.x, g1.y, 0.0});
    const hal::Pixel i0 = p0 ? *p0 : s.pixels_[static_cast<std::size_t>(s.order_[first].second)];
    const hal::Pixel i1 = p1 ? *p1 : s.pixels_[static_cast<std::size_t>(s.order_[last].second)];
    // A piece that fails as a whole may still hold a line: one seen past robots' legs has long
    // hidden stretches (too sparse), one that runs on into a robot's white feet is no paint there
    // (the check). Its parts either side of the widest gap between its points are judged alone.
    const auto split = [&]() {
      if (depth >= params_.max_split_depth || count < 2 * params_.min_inliers) return false;
      std::size_t cut = first;
      double widest = -1.0;
      for (std::size_t i = first; i < last; ++i) {
        const double gap = s.order_[i + 1].first - s.order_[i].first;
        if (gap > widest) {
          widest = gap;
          cut = i;
        }
      }
      ++out.stats.splits;
      self(self, first, cut, depth + 1);
      self(self, cut + 1, last, depth + 1);
      return true;
    };
    if (count < min_support(line, t0, t1, check) * norm(i1.u - i0.u, i1.v - i0.v) / scan_stride) {
      if (!split()) ++out.stats.sparse_rejected;
      return;
    }
    // The picture must show paint along it (a fit through a few true points and robots' feet
    // would not).
    const LineCheck::Verdict verdict = check != nullptr ? check->judge_piece(g0, g1) : LineCheck::Verdict{};
    if (!verdict.accepted) {
      if (!split()) ++out.stats.check_rejected;
      return;
    }
    any = true;
    FieldLine& f = out.lines[out.count++];
    f.ground_start = g0;
    f.ground_end = g1;
    f.length_m = t1 - t0;
    f.inliers = count;
    f.image_start = i0;
    f.image_end = i1;
    trim_to_paint(f, k, pose, verdict.span);
  };
  std::size_t first = 0;
  for (std::size_t i = 1; i <= s.order_.size(); ++i) {
    if (i == s.order_.size() || s.order_[i].first - s.order_[i - 1].first > params_.split_gap_m) {
      if (!s.order_.empty()) close_piece(close_piece, first, i - 1, 0);
      first = i;
    }
  }
  return any;
}

void RansacLineFinder::merge(LineSet& out, const hal::CameraIntrinsics& k, const hal::CameraPose& pose,
                             const LineCheck* check) const noexcept {
  const double cos_max = std::cos(params_.merge_angle_deg * std::numbers::pi / 180.0);
  const auto as_line = [](const FieldLine& f) {
    const double len = std::max(f.length_m, 1e-9);
    return Line2{f.ground_start, (f.ground_end.x - f.ground_start.x) / len, (f.ground_end.y - f.ground_start.y) / len};
  };
  bool merged = true;
  while (merged) {
    merged = false;
    for (std::size_t a = 0; a < out.count && !merged; ++a) {
      for (std::size_t b = a + 1; b < out.count && !merged; ++b) {
        const FieldLine& fa = out.lines[a];
        const FieldLine& fb = out.lines[b];
        const Line2 la = as_line(fa);
        const Line2 lb = as_line(fb);
        if (std::abs(la.dx * lb.dx + la.dy * lb.dy) < cos_max) continue;
        if (std::abs(la.signed_distance(fb.ground_start)) > params_.merge_offset_m ||
            std::abs(la.signed_distance(fb.ground_end)) > params_.merge_offset_m ||
            std::abs(lb.signed_distance(fa.ground_start)) > params_.merge_offset_m ||
            std::abs(lb.signed_distance(fa.ground_end)) > params_.merge_offset_m) {
          continue;
        }
        const double tb0 = la.along(fb.ground_start);
        const double tb1 = la.along(fb.ground_end);
        const double gap = std::max({0.0, std::min(tb0, tb1) - fa.length_m, -std::max(tb0, tb1)});
        if (gap > params_.split_gap_m) continue;
        // Extend the longer segment's line over both.
        const Line2 base = fa.length_m >= fb.length_m ? la : lb;
        double t_min = 1e300, t_max = -1e300;
        for (const hal::RobotPoint& p : {fa.ground_start, fa.ground_end, fb.ground_start, fb.ground_end}) {
          t_min = std::min(t_min, base.along(p));
          t_max = std::max(t_max, base.along(p));
        }
        FieldLine m = fa;
        m.ground_start = base.at(t_min);
        m.ground_end = base.at(t_max);
        // Two pieces in line across a robot's feet are not one painted line: the whole must look
        // like paint too (a line behind the ball still does).
        const LineCheck::Verdict verdict =
            check != nullptr ? check->judge_piece(m.ground_start, m.ground_end) : LineCheck::Verdict{};
        if (!verdict.accepted) continue;
        m.length_m = t_max - t_min;
        m.inliers = fa.inliers + fb.inliers;
        if (const auto p0 = hal::project(k, pose, {m.ground_start.x, m.ground_start.y, 0.0})) m.image_start = *p0;
        if (const auto p1 = hal::project(k, pose, {m.ground_end.x, m.ground_end.y, 0.0})) m.image_end = *p1;
        trim_to_paint(m, k, pose, verdict.span);
        out.lines[a] = m;
        for (std::size_t c = b + 1; c < out.count; ++c) out.lines[c - 1] = out.lines[c];
        --out.count;
        ++out.stats.merges;
        merged = true;
      }
    }
  }
}

}  // namespace ringlet::vision
