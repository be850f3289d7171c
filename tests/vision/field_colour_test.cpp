// The adaptive colour classification on frames coloured like the real NAO photos of issue 10:
// carpet V 112–128 (the default table's field stops at V 122), bluish-white lines with U 95–103
// (the table's line starts at U 106), and a backlit frame with line Y 157–168 over a dim field
// (the table's line starts at Y 165). The adaptive classifier must label carpet field and lines
// line (pixel precision and recall ≥ 0.9) where the default table fails, follow exposure changes
// from frame to frame, and fall back when there is no field in view.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "ringlet/vision/class_image.hpp"
#include "ringlet/vision/field_colour.hpp"
#include "ringlet/vision/horizon.hpp"
#include "ringlet/vision/pipeline.hpp"
#include "synthetic_field.hpp"

namespace ringlet::vision {
namespace {

using testing::Camera;

// YUV of each surface; Y and V may vary across the image (low frequency, as light and carpet do).
struct Palette {
  int field_y = 95, field_u = 110, field_v_left = 112, field_v_right = 128;
  int line_y_lo = 190, line_y_hi = 210, line_u_lo = 95, line_u_hi = 103, line_v = 126;
  int wall_y = 120, wall_u = 128, wall_v = 128;
  int noise = 3;  // ± per channel
};

Palette real_carpet() { return {}; }
Palette backlit() {
  Palette p;
  p.field_y = 58;
  p.field_u = 114;
  p.field_v_left = 116;
  p.field_v_right = 122;
  p.line_y_lo = 157;
  p.line_y_hi = 168;
  p.line_u_lo = 98;
  p.line_u_hi = 104;
  p.line_v = 128;
  p.wall_y = 200;  // bright windows behind
  return p;
}

struct Labelled {
  testing::Frame frame;            // YUYV
  std::vector<ColourClass> truth;  // per pixel
};

std::uint32_t mix(std::uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}

int jitter(int c, int noise, std::uint32_t h) {
  return std::clamp(c + static_cast<int>(h % static_cast<std::uint32_t>(2 * noise + 1)) - noise, 0, 255);
}

// The synthetic field scene (lines, circle; no ball) rendered for its geometry, then each surface
// given the palette's YUV; pixel pairs share their chroma as a YUYV camera's do. `gain` scales
// every luminance (exposure).
Labelled render(const Palette& pal, double gain = 1.0, std::uint64_t sequence = 0) {
  Camera cam;
  testing::Scene scene = testing::field_scene();
  scene.ball.reset();
  scene.noise = 0;
  const testing::Frame geometry = testing::render(scene, cam, hal::PixelFormat::kBgr8);
  Labelled out;
  const int w = cam.k.width, h = cam.k.height;
  out.truth.resize(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
  std::vector<Yuv> yuv(out.truth.size());
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x);
      const std::uint8_t* p = geometry.bytes.data() + 3 * i;
      const double t = static_cast<double>(x) / (w - 1);
      const auto seed = static_cast<std::uint32_t>(i) * 3U + static_cast<std::uint32_t>(sequence) * 7919U;
      int cy = 0, cu = 0, cv = 0;
      ColourClass c = ColourClass::kOther;
      if (p[1] == testing::kGreen.g && p[0] == testing::kGreen.b) {
        c = ColourClass::kField;
        cy = pal.field_y;
        cu = pal.field_u;
        cv = static_cast<int>(std::lround(pal.field_v_left + t * (pal.field_v_right - pal.field_v_left)));
      } else if (p[0] == testing::kWhite.b) {
        c = ColourClass::kLine;
        cy = static_cast<int>(std::lround(pal.line_y_lo + t * (pal.line_y_hi - pal.line_y_lo)));
        cu = static_cast<int>(std::lround(pal.line_u_lo + (1.0 - t) * (pal.line_u_hi - pal.line_u_lo)));
        cv = pal.line_v;
      } else {
        cy = pal.wall_y;
        cu = pal.wall_u;
        cv = pal.wall_v;
      }
      cy = static_cast<int>(std::lround(cy * gain));
      out.truth[i] = c;
      yuv[i] = {static_cast<std::uint8_t>(jitter(cy, pal.noise, mix(seed))),
                static_cast<std::uint8_t>(jitter(cu, pal.noise, mix(seed + 1))),
                static_cast<std::uint8_t>(jitter(cv, pal.noise, mix(seed + 2)))};
    }
  }
  testing::Frame& f = out.frame;
  f.view.sequence = sequence;
  f.view.format = hal::PixelFormat::kYuyv;
  f.view.width = w;
  f.view.height = h;
  f.view.stride = 2 * w;
  f.bytes.resize(static_cast<std::size_t>(f.view.stride) * static_cast<std::size_t>(h));
  for (std::size_t i = 0; i + 1 < yuv.size(); i += 2) {
    f.bytes[2 * i] = yuv[i].y;
    f.bytes[2 * i + 1] = static_cast<std::uint8_t>((yuv[i].u + yuv[i + 1].u + 1) / 2);
    f.bytes[2 * i + 2] = yuv[i + 1].y;
    f.bytes[2 * i + 3] = static_cast<std::uint8_t>((yuv[i].v + yuv[i + 1].v + 1) / 2);
  }
  f.view.data = f.bytes.data();
  return out;
}

struct Score {
  double precision = 0.0, recall = 0.0;
};

// Pixel precision and recall of class c over the classified rows.
Score score(const ClassImage& classes, const Labelled& l, ColourClass c) {
  long tp = 0, predicted = 0, labelled = 0;
  for (int y = classes.first_row(); y < classes.height(); ++y) {
    for (int x = 0; x < classes.width(); ++x) {
      const bool truth = l.truth[static_cast<std::size_t>(y) * static_cast<std::size_t>(classes.width()) +
                                 static_cast<std::size_t>(x)] == c;
      const bool said = classes.at(x, y) == c;
      tp += truth && said;
      predicted += said;
      labelled += truth;
    }
  }
  return {predicted == 0 ? 1.0 : static_cast<double>(tp) / static_cast<double>(predicted),
          labelled == 0 ? 1.0 : static_cast<double>(tp) / static_cast<double>(labelled)};
}

struct Classified {
  ClassImage adaptive{640, 480};
  ClassImage table{640, 480};
  FieldColourEstimate estimate;
};

Classified classify_both(const Labelled& l) {
  Camera cam;
  std::vector<int> rows(640);
  const int first = horizon_rows(cam.k, cam.pose(), 2, rows);
  Classified out;
  out.estimate = FieldColourEstimator::measure(l.frame.view, rows, {});
  EXPECT_TRUE(out.estimate.valid);
  AdaptiveClassifier adaptive;
  adaptive.build(out.estimate, 640, 480);
  EXPECT_TRUE(out.adaptive.classify(l.frame.view, adaptive, first, 1));
  EXPECT_TRUE(out.table.classify(l.frame.view, ColourTable::from_thresholds({}), first, 1));
  return out;
}

TEST(FieldColour, RealCarpetColoursAdaptiveLabelsFieldAndLinesWhereTheDefaultTableFails) {
  const Labelled l = render(real_carpet());
  const Classified c = classify_both(l);
  EXPECT_NEAR(c.estimate.y, 95, 3);
  EXPECT_NEAR(c.estimate.u, 110, 3);
  EXPECT_NEAR(c.estimate.v, 120, 4);
  EXPECT_GT(c.estimate.confidence, 0.7);
  const Score field = score(c.adaptive, l, ColourClass::kField);
  const Score line = score(c.adaptive, l, ColourClass::kLine);
  EXPECT_GE(field.precision, 0.9);
  EXPECT_GE(field.recall, 0.9);
  EXPECT_GE(line.precision, 0.9);
  EXPECT_GE(line.recall, 0.9);
  // The default table: carpet with V > 122 is not field, lines with U < 106 are not line.
  const Score table_field = score(c.table, l, ColourClass::kField);
  const Score table_line = score(c.table, l, ColourClass::kLine);
  EXPECT_LT(table_field.recall, 0.8);
  EXPECT_LT(table_line.recall, 0.5);
  std::printf("real carpet: adaptive field P %.3f R %.3f, line P %.3f R %.3f; table field R %.3f, line R %.3f\n",
              field.precision, field.recall, line.precision, line.recall, table_field.recall, table_line.recall);
}

TEST(FieldColour, BacklitFrameDimFieldAndGreyLines) {
  const Labelled l = render(backlit());
  const Classified c = classify_both(l);
  EXPECT_NEAR(c.estimate.y, 58, 3);
  const Score field = score(c.adaptive, l, ColourClass::kField);
  const Score line = score(c.adaptive, l, ColourClass::kLine);
  EXPECT_GE(field.precision, 0.9);
  EXPECT_GE(field.recall, 0.9);
  EXPECT_GE(line.precision, 0.9);
  EXPECT_GE(line.recall, 0.9);
  const Score table_line = score(c.table, l, ColourClass::kLine);
  EXPECT_LT(table_line.recall, 0.5);
  std::printf("backlit: adaptive field P %.3f R %.3f, line P %.3f R %.3f; table line R %.3f\n", field.precision,
              field.recall, line.precision, line.recall, table_line.recall);
}

TEST(FieldColour, TablesAgreeWithTheComparisonRule) {
  const Labelled l = render(real_carpet());
  Camera cam;
  std::vector<int> rows(640);
  horizon_rows(cam.k, cam.pose(), 2, rows);
  AdaptiveClassifier adaptive;
  adaptive.build(FieldColourEstimator::measure(l.frame.view, rows, {}), 640, 480);
  int differ = 0, compared = 0;
  for (int y = 0; y < 256; y += 3)
    for (int u = 0; u < 256; u += 4)  // bin-aligned chroma: the tables test the bin centre
      for (int v = 0; v < 256; v += 4) {
        const auto uu = static_cast<std::uint8_t>(u + 2), vv = static_cast<std::uint8_t>(v + 2);
        for (const int cell : {0, 9, 15}) {
          ++compared;
          differ += adaptive.classify(static_cast<std::uint8_t>(y), uu, vv, cell) !=
                    adaptive.classify_by_comparison(static_cast<std::uint8_t>(y), uu, vv, cell);
        }
      }
  EXPECT_GT(compared, 100000);
  EXPECT_EQ(differ, 0);
}

TEST(FieldColour, ExposureChangesAreFollowedFrameToFrame) {
  Camera cam;
  VisionPipeline pipeline(VisionConfig{}, ColourTable::from_thresholds({}));
  // Slow drift (smoothed) then a sudden step (reset), then back.
  const double gains[] = {1.0, 0.95, 0.9, 0.85, 0.8, 0.8, 0.8, 1.35, 1.35, 1.0};
  std::uint64_t seq = 0;
  bool saw_reset = false;
  for (const double g : gains) {
    const Labelled l = render(real_carpet(), g, ++seq);
    const VisionResult& r = pipeline.process(l.frame.view, cam.head);
    ASSERT_TRUE(r.field_colour.valid);
    EXPECT_EQ(r.field_colour.source, ColourSource::kFrame);
    // Within the smoothing lag of the true field luminance.
    EXPECT_NEAR(r.field_colour.y, 95.0 * g, 6.0) << "gain " << g;
    saw_reset = saw_reset || r.field_colour.reset;
    const Score line = score(pipeline.classes(), l, ColourClass::kLine);
    const Score field = score(pipeline.classes(), l, ColourClass::kField);
    EXPECT_GE(line.recall, 0.9) << "gain " << g;
    EXPECT_GE(field.recall, 0.9) << "gain " << g;
    EXPECT_GE(r.line_count, 2U) << "gain " << g;
  }
  EXPECT_TRUE(saw_reset);  // the step to 1.35 restarted the smoothing
}

TEST(FieldColour, NoFieldInViewHoldsThenFallsBackToTheTable) {
  Camera cam;
  AdaptiveColourParams params;
  params.hold_frames = 3;
  VisionConfig config;
  config.adaptive = params;
  VisionPipeline pipeline(config, ColourTable::from_thresholds({}));
  const Labelled field = render(real_carpet());
  ASSERT_TRUE(pipeline.process(field.frame.view, cam.head).field_colour.valid);
  // A grey wall fills the view: no green-ish dominant chroma.
  Palette wall = real_carpet();
  wall.field_u = wall.line_u_lo = wall.line_u_hi = 128;
  wall.field_v_left = wall.field_v_right = wall.line_v = 128;
  wall.line_y_lo = wall.line_y_hi = wall.field_y = 120;
  const Labelled grey = render(wall);
  EXPECT_FALSE(FieldColourEstimator::measure(grey.frame.view, std::vector<int>(640, 0), params).valid);
  for (int k = 1; k <= 3; ++k) {
    const VisionResult& r = pipeline.process(grey.frame.view, cam.head);
    EXPECT_TRUE(r.field_colour.valid) << k;
    EXPECT_EQ(r.field_colour.source, ColourSource::kPrevious) << k;
    EXPECT_EQ(r.field_colour.age, k);
    EXPECT_LT(r.field_colour.confidence, 0.9);
  }
  const VisionResult& r = pipeline.process(grey.frame.view, cam.head);
  EXPECT_FALSE(r.field_colour.valid);
  EXPECT_EQ(r.field_colour.source, ColourSource::kTable);
  EXPECT_EQ(r.field_colour.confidence, 0.0);
  // And the field again: measured afresh.
  EXPECT_EQ(pipeline.process(field.frame.view, cam.head).field_colour.source, ColourSource::kFrame);
}

// A dull carpet below a grey floor and grey robots covering most of the view: the grey's mass
// sits in the chroma bins next to the carpet's. The field's peak and centre are taken over
// green-ish bins only, so the grey neither wins the peak nor drags the cluster's median to grey.
// A 640 × 480 YUYV frame of two surfaces: `second(x, y)` picks, per pixel pair, `b` over `a`
// (mean Y, U, V and the ± jitter of Y and of U, V).
struct Surface {
  int y, u, v, y_noise, uv_noise;
};
template <typename Pick>
testing::Frame two_surfaces(const Surface& a, const Surface& b, Pick second) {
  const int w = 640, h = 480;
  testing::Frame f;
  f.view.format = hal::PixelFormat::kYuyv;
  f.view.width = w;
  f.view.height = h;
  f.view.stride = 2 * w;
  f.bytes.resize(static_cast<std::size_t>(f.view.stride) * h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; x += 2) {
      const Surface& s = second(x, y) ? b : a;
      const auto seed = static_cast<std::uint32_t>(y * w + x);
      std::uint8_t* p = f.bytes.data() + static_cast<std::size_t>(y * f.view.stride + 2 * x);
      p[0] = static_cast<std::uint8_t>(jitter(s.y, s.y_noise, mix(seed)));
      p[1] = static_cast<std::uint8_t>(jitter(s.u, s.uv_noise, mix(seed + 1)));
      p[2] = static_cast<std::uint8_t>(jitter(s.y, s.y_noise, mix(seed + 2)));
      p[3] = static_cast<std::uint8_t>(jitter(s.v, s.uv_noise, mix(seed + 3)));
    }
  }
  f.view.data = f.bytes.data();
  return f;
}

// The estimate of a frame whose every column is ground from the top row down.
FieldColourEstimate estimate_below_row_0(const testing::Frame& f, const AdaptiveColourParams& params = {}) {
  const std::vector<int> rows(static_cast<std::size_t>(f.view.width), 0);
  return FieldColourEstimator::measure(f.view, rows, params);
}

TEST(FieldColour, DullCarpetBesideMoreGreyIsStillTheField) {
  // The carpet below row 300: 37.5 % of the view.
  const testing::Frame f = two_surfaces({125, 127, 129, 3, 2}, {100, 118, 124, 3, 2}, [](int, int y) { return y >= 300; });
  const FieldColourEstimate e = estimate_below_row_0(f);
  ASSERT_TRUE(e.valid);
  EXPECT_NEAR(e.u, 118, 2);
  EXPECT_NEAR(e.v, 124, 2);
  EXPECT_NEAR(e.y, 100, 3);
  EXPECT_NEAR(e.confidence, 0.375, 0.03);
}

// Near the camera a painted line is wide: it may cover most of a colour cell. Cream paint in warm
// light has nearly the field's chroma, so its samples pass for field; were they counted in the
// cell's carpet luminance, that cell's line threshold would rise above the paint itself (seen on
// rendered daylight frames: a cell's "field" Y of 210 from the paint over carpet of 100).
TEST(FieldColour, AWideLineFillingACellIsNotThatCellsCarpet) {
  const int w = 640, h = 480;
  // Cell (column 3, row 6) spans x 240-319, y 360-419; the paint covers x 244-303 (three quarters).
  // Field chroma (-28, -4); the paint's (-31, +1) is within the field's cone.
  const testing::Frame f = two_surfaces({100, 100, 124, 3, 1}, {220, 97, 129, 3, 1},
                                        [](int x, int y) { return x >= 244 && x < 304 && y >= 360 && y < 420; });
  const FieldColourEstimate e = estimate_below_row_0(f);
  ASSERT_TRUE(e.valid);
  const int cell = 6 * kColourCellsX + 3;
  ASSERT_NE((e.field_cells >> cell) & 1U, 0U) << "the paint's samples still count as field there";
  EXPECT_NEAR(e.cell_y[static_cast<std::size_t>(cell)], 100, 6) << "the carpet's luminance, not the paint's";
  AdaptiveClassifier adaptive;
  adaptive.build(e, w, h);
  EXPECT_EQ(adaptive.classify(220, 97, 129, cell), ColourClass::kLine);
  EXPECT_EQ(adaptive.classify(100, 100, 124, cell), ColourClass::kField);
}

// A measured estimate of one field colour (Y, U, V) and luminance spread over every cell, each
// holding field.
FieldColourEstimate uniform_estimate(int y, int u, int v, int spread) {
  FieldColourEstimate e;
  e.valid = true;
  e.source = ColourSource::kFrame;
  e.y = static_cast<std::uint8_t>(y);
  e.u = static_cast<std::uint8_t>(u);
  e.v = static_cast<std::uint8_t>(v);
  e.y_spread = static_cast<std::uint8_t>(spread);
  e.uv_spread = 2;
  e.cell_y.fill(static_cast<std::uint8_t>(y));
  e.field_cells = ~std::uint64_t{0};
  return e;
}

// Shade scales chroma with brightness. A pixel with a fraction of the field's chroma is shaded
// carpet when it is darker than the field, but a tinted grey (a ball's white in warm light, a
// robot's shell) when it is as bright or brighter.
TEST(FieldColour, PaleFieldChromaIsFieldOnlyInShade) {
  AdaptiveClassifier adaptive;
  adaptive.build(uniform_estimate(100, 108, 118, 4), 640, 480);  // field chroma (−20, −10)
  const int cell = 20;
  // Chroma (−10, −6), a chroma bin's centre: 0.52 of the field's.
  EXPECT_EQ(adaptive.classify(50, 118, 122, cell), ColourClass::kField);    // shade
  EXPECT_EQ(adaptive.classify(110, 118, 122, cell), ColourClass::kOther);   // a tinted grey
  EXPECT_EQ(adaptive.classify(150, 118, 122, cell), ColourClass::kLine);    // bright: a line or a ball's white
  // The field's own chroma is field at any brightness below a line's.
  EXPECT_EQ(adaptive.classify(60, 108, 118, cell), ColourClass::kField);
  EXPECT_EQ(adaptive.classify(120, 108, 118, cell), ColourClass::kField);
  for (const int luma : {50, 110, 150}) {
    const auto y = static_cast<std::uint8_t>(luma);
    EXPECT_EQ(adaptive.classify(y, 118, 122, cell), adaptive.classify_by_comparison(y, 118, 122, cell));
  }
}

// Sun scales the carpet's chroma with its brightness: in rendered daylight frames (val_s101 frame
// 1049) shaded carpet at (Y 87, U 107, V 121) lay beside sunlit stripes at (Y 200, U 66, V 118),
// 2.8 times the shade's chroma. Beyond the cone's old end (2.5) the stripes were "other": a line
// crossing them had no field on either side, and the robots' candidates ran into them.
TEST(FieldColour, SunlitCarpetWithAlmostThreeTimesTheShadesChromaIsField) {
  const int w = 640, h = 480;
  const auto sunlit = [](int, int y) { return y >= 180 && y < 300; };  // cell rows 3 and 4
  const testing::Frame f = two_surfaces({87, 107, 121, 3, 1}, {200, 66, 118, 3, 1}, sunlit);
  const FieldColourEstimate e = estimate_below_row_0(f);
  ASSERT_TRUE(e.valid);
  EXPECT_NEAR(e.y, 87, 3) << "the shade covers most of the view";
  const int cell = 3 * kColourCellsX + 2;
  ASSERT_NE((e.field_cells >> cell) & 1U, 0U) << "the sunlit cells hold field";
  EXPECT_NEAR(e.cell_y[static_cast<std::size_t>(cell)], 200, 6) << "their carpet is the sunlit one";
  AdaptiveClassifier adaptive;
  adaptive.build(e, w, h);
  EXPECT_EQ(adaptive.classify(200, 66, 118, cell), ColourClass::kField);
  EXPECT_EQ(adaptive.classify(250, 126, 127, cell), ColourClass::kLine) << "paint in the sun";
  EXPECT_EQ(adaptive.classify(87, 107, 121, 0), ColourClass::kField);
  // The cone still ends: chroma four times the field's (a saturated green board) is not carpet.
  EXPECT_EQ(adaptive.classify(200, 44, 100, cell), ColourClass::kOther);
  EXPECT_EQ(adaptive.classify(200, 66, 118, cell), adaptive.classify_by_comparison(200, 66, 118, cell));

  // With the cone ending at 2.5, as before, the same stripes were no field.
  AdaptiveColourParams old;
  old.cone_t_max = 2.5;
  const FieldColourEstimate e_old = estimate_below_row_0(f, old);
  ASSERT_TRUE(e_old.valid);
  EXPECT_EQ((e_old.field_cells >> cell) & 1U, 0U);
}

// The classifier for a uniform field luminance `y` and luminance spread `spread` over every cell.
AdaptiveClassifier classifier_for(int y, int spread, const AdaptiveColourParams& params = {}) {
  AdaptiveClassifier adaptive(params);
  adaptive.build(uniform_estimate(y, 108, 118, spread), 640, 480);
  return adaptive;
}

TEST(FieldColour, BrightCarpetLeavesThePaintRoomBelowWhite) {
  const int cell = 20;
  // Ordinary carpet: the margin, max(28, 3·spread, 0.25·Y), stands (100 + 28).
  EXPECT_EQ(classifier_for(100, 4).line_y_min(cell), 128);
  // Overexposed carpet at Y 200: 0.25·Y would ask for 250, so paint clipped at 240 could never
  // pass; at most half the way to white is asked (200 + 28).
  const AdaptiveClassifier bright = classifier_for(200, 4);
  EXPECT_EQ(bright.line_y_min(cell), 228);
  EXPECT_EQ(bright.classify(240, 128, 128, cell), ColourClass::kLine);
  EXPECT_EQ(bright.classify(220, 128, 128, cell), ColourClass::kOther) << "grey just above the carpet is no paint";
  // Sun and shade across the view: a spread of 30 would ask for 113 + 90; half the headroom is 71.
  EXPECT_EQ(classifier_for(113, 30).line_y_min(cell), 113 + 71);
  // Right under white the floor, line_margin, would ask for more than 255 (val_s101 frame 1164:
  // sunlit carpet at Y 227–230, its paint clipped at 255, no line at all). The threshold stops at
  // line_y_max, and above the carpet: chroma tells the paint from the saturated carpet.
  const AdaptiveClassifier white = classifier_for(232, 2);
  EXPECT_EQ(white.line_y_min(cell), 245);
  EXPECT_EQ(white.classify(255, 128, 128, cell), ColourClass::kLine) << "clipped paint";
  EXPECT_EQ(white.classify(240, 108, 118, cell), ColourClass::kField) << "carpet brighter still is carpet";
  EXPECT_EQ(white.classify(255, 128, 128, cell), white.classify_by_comparison(255, 128, 128, cell));
  EXPECT_EQ(classifier_for(250, 2).line_y_min(cell), 251) << "never at the carpet's own luminance";
  AdaptiveColourParams uncapped;
  uncapped.line_y_max = 255 + 28;
  const AdaptiveClassifier before = classifier_for(232, 2, uncapped);
  EXPECT_EQ(before.line_y_min(cell), 260) << "without the cap: no line in that cell";
  EXPECT_EQ(before.classify(255, 128, 128, cell), ColourClass::kOther);
}

// Sun and shade in large patches (val_s101 frame 1082): the frame's field is the sunlit carpet
// (Y 157, U 68), and a cell wholly in shade has the shade's luminance as its carpet (Y 94), its
// chroma (U 96) 0.55 of the sunlit one: pale. Pale chroma is field where darker than the field in
// light; measured against the shaded cell's own carpet (0.85 × 94) the shade itself was "other",
// and a line across it had no field on either side.
TEST(FieldColour, ShadeInACellWhollyInShadeIsField) {
  FieldColourEstimate e = uniform_estimate(157, 68, 130, 9);
  const int shade = 3 * kColourCellsX + 4;
  e.cell_y[static_cast<std::size_t>(shade)] = 94;
  AdaptiveClassifier adaptive;
  adaptive.build(e, 640, 480);
  EXPECT_EQ(adaptive.classify(99, 96, 126, shade), ColourClass::kField) << "the shade";
  EXPECT_EQ(adaptive.classify(99, 96, 126, shade), adaptive.classify_by_comparison(99, 96, 126, shade));
  EXPECT_EQ(adaptive.classify(130, 126, 128, shade), ColourClass::kLine) << "paint in the shade: 94 + 28 and more";
  EXPECT_EQ(adaptive.classify(182, 69, 129, 0), ColourClass::kField) << "the sunlit carpet";
  // Still: pale chroma as bright as the field in light is no carpet (a robot's tinted shell).
  EXPECT_EQ(adaptive.classify(140, 98, 129, 0), ColourClass::kOther);
  EXPECT_EQ(adaptive.classify(140, 98, 129, 0), adaptive.classify_by_comparison(140, 98, 129, 0));
  EXPECT_EQ(adaptive.classify(99, 98, 129, 0), ColourClass::kField) << "the same chroma in shade";
}

TEST(FieldColour, TableModeNeverEstimates) {
  Camera cam;
  VisionConfig config;
  config.colour_mode = ColourMode::kTable;
  VisionPipeline pipeline(config, ColourTable::from_thresholds({}));
  const Labelled l = render(real_carpet());
  const VisionResult& r = pipeline.process(l.frame.view, cam.head);
  EXPECT_FALSE(r.field_colour.valid);
  EXPECT_EQ(r.field_colour.source, ColourSource::kTable);
  EXPECT_LT(score(pipeline.classes(), l, ColourClass::kLine).recall, 0.5);
}

TEST(FieldColour, AdaptivePipelineFindsTheLinesTheTableMisses) {
  Camera cam;
  const Labelled l = render(real_carpet());
  VisionConfig adaptive;
  VisionConfig table;
  table.colour_mode = ColourMode::kTable;
  VisionPipeline a(adaptive, ColourTable::from_thresholds({}));
  VisionPipeline t(table, ColourTable::from_thresholds({}));
  const std::size_t with_adaptive = a.process(l.frame.view, cam.head).line_count;
  const std::size_t with_table = t.process(l.frame.view, cam.head).line_count;
  EXPECT_GE(with_adaptive, 2U);  // the halfway line and the touch line
  EXPECT_LT(with_table, with_adaptive);
}

}  // namespace
}  // namespace ringlet::vision
