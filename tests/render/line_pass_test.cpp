// Lines (line_pass.cpp): round joins and caps, coverage at one sample,
// uniform intensity, the part in front of the near plane.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "render/layer_key.hpp"
#include "render/screen_bounds.hpp"
#include "renderer_fixture.hpp"
#include "support/test_files.hpp"

namespace rollspin::render {
namespace {

// A view whose world x, y are its normalised device coordinates (identity
// camera), placed off the image's origin so that the lines' window-space
// arithmetic is exercised away from (0, 0).
View screenView(int x, int y, int w, int h) {
  View v = flatView(x, y, w, h, glm::vec3(0.0f));
  v.camera.viewFromWorld = glm::mat4(1.0f);
  v.camera.clipFromView = glm::mat4(1.0f);
  return v;
}

// The world point that `v` draws at its pixel (px, py), top-left origin.
glm::vec3 atViewPixel(const View& v, float px, float py) {
  return {px / float(v.width) * 2.0f - 1.0f, 1.0f - py / float(v.height) * 2.0f, 0.0f};
}

// A thick white polyline on black with a 160° turn and two free ends: the
// pixels around the corner and the ends tell a capsule (round join, round
// caps) from a segment extended into a square by half its width.
TEST_F(RendererTest, PolylinesHaveRoundJoinsAndRoundCaps) {
  constexpr float kWidth = 20.0f, kHalf = kWidth / 2.0f;
  const glm::vec2 a(40.0f, 100.0f), b(160.0f, 100.0f);  // view pixels, +y down
  const float turn = glm::radians(160.0f);
  const glm::vec2 c = b + 100.0f * glm::vec2(std::cos(turn), std::sin(turn));  // back left and down
  for (int samples : {4, 1}) {
    SCOPED_TRACE(::testing::Message() << samples << " sample(s)");
    DrawList list;
    list.width = 320;
    list.height = 260;
    list.msaaSamples = samples;
    const View v = screenView(60, 30, 240, 200);
    list.views = {v};
    PolylineItem line;
    line.points = {atViewPixel(v, a.x, a.y), atViewPixel(v, b.x, b.y), atViewPixel(v, c.x, c.y)};
    line.color = {1, 1, 1, 1};
    line.widthPx = kWidth;
    line.depthTested = false;
    list.polylines.push_back(line);
    const media::Image img = renderer_->render(list);
    // The pixel that holds view point p: all its points lie within √2 of p.
    auto at = [&](glm::vec2 p) { return int(img.pixel(v.x + int(std::floor(p.x)), v.y + int(std::floor(p.y)))[0]); };
    // Whole pixels within half a width of the corner: line; beyond it,
    // where a square corner reached (|x|, |y| ≤ half a width from the
    // vertex along the first segment): background.
    for (int k = 0; k < 12; ++k) {
      const float angle = glm::radians(30.0f * float(k));
      const glm::vec2 inside = b + (kHalf - 1.5f) * glm::vec2(std::cos(angle), std::sin(angle));
      EXPECT_EQ(at(inside), 255) << "join, " << 30 * k << "°";
    }
    for (const glm::vec2 corner : {glm::vec2(8.5f, -8.5f), glm::vec2(8.5f, 8.5f)})
      EXPECT_EQ(at(b + corner), 0) << "outer corner " << corner.x << "," << corner.y;
    // The free ends: the tip along the axis is line, the square cap's
    // corner background.
    EXPECT_EQ(at(a + glm::vec2(-(kHalf - 1.5f), 0)), 255) << "start tip";
    EXPECT_EQ(at(a + glm::vec2(-8.5f, -8.5f)), 0) << "start cap corner";
    EXPECT_EQ(at(a + glm::vec2(-8.5f, 8.5f)), 0) << "start cap corner";
    const glm::vec2 along = glm::normalize(c - b), across(-along.y, along.x);
    EXPECT_EQ(at(c + (kHalf - 1.5f) * along), 255) << "end tip";
    EXPECT_EQ(at(c + 8.5f * (along + across)), 0) << "end cap corner";
    EXPECT_EQ(at(c + 8.5f * (along - across)), 0) << "end cap corner";
    // Nothing outside the view (the line's window position is its own).
    EXPECT_EQ(img.pixel(v.x - 1, v.y + int(a.y))[0], 0);
  }
}

// At one sample a line's coverage is its alpha: a thin diagonal line on
// black leaves intermediate values along its edges, and carries as much
// light per column as at 4× MSAA.
TEST_F(RendererTest, LinesAtOneSampleAreAntialiasedByCoverage) {
  DrawList list;
  list.width = 120;
  list.height = 80;
  list.views = {screenView(0, 0, 120, 80)};
  PolylineItem line;
  line.points = {atViewPixel(list.views[0], 10.0f, 20.0f), atViewPixel(list.views[0], 110.0f, 57.0f)};
  line.color = {1, 1, 1, 1};
  line.widthPx = 2.5f;
  line.depthTested = false;
  list.polylines.push_back(line);
  const media::Image multisampled = renderer_->render(list);
  list.msaaSamples = 1;
  const media::Image covered = renderer_->render(list);
  for (int x = 30; x <= 90; x += 10) {
    long long sumMulti = 0, sumCovered = 0;
    int partial = 0;
    for (int y = 0; y < 80; ++y) {
      sumMulti += multisampled.pixel(x, y)[0];
      sumCovered += covered.pixel(x, y)[0];
      partial += covered.pixel(x, y)[0] > 0 && covered.pixel(x, y)[0] < 255 ? 1 : 0;
    }
    EXPECT_GE(partial, 2) << "column " << x;
    EXPECT_NEAR(double(sumCovered), double(sumMulti), 0.15 * double(sumMulti)) << "column " << x;
  }
}

// A long straight trail of short segments at 2400 px: every column across
// it carries the same amount of line (no darker or brighter joints).
TEST_F(RendererTest, StraightPolylineHasUniformIntensityAt2400Px) {
  DrawList list;
  list.width = 2400;
  list.height = 200;
  const View v = screenView(0, 0, 2400, 200);
  list.views = {v};
  PolylineItem line;
  line.color = {1, 1, 1, 1};
  line.widthPx = 5.0f;  // the marker trail's width at this size
  // 300 segments of ≈ 7.4 px, rising 90 px over 2200 px.
  for (int k = 0; k <= 300; ++k) {
    const float t = float(k) / 300.0f;
    line.points.push_back(atViewPixel(v, 100.0f + 2200.0f * t, 145.0f - 90.0f * t));
  }
  list.polylines.push_back(line);
  const media::Image img = renderer_->render(list);
  double lo = 1e30, hi = 0.0, sum = 0.0;
  int columns = 0;
  for (int x = 150; x < 2250; ++x) {
    double column = 0.0;
    for (int y = 0; y < img.height; ++y) column += img.pixel(x, y)[0];
    lo = std::min(lo, column), hi = std::max(hi, column), sum += column;
    ++columns;
  }
  const double mean = sum / columns;
  EXPECT_GT(mean, 255.0 * 4.0);  // the line is there, about its width deep
  EXPECT_LE((hi - lo) / mean, 0.10) << "column sums from " << lo << " to " << hi;
}

// A segment that reaches between the eye and the near plane is drawn up to
// where the near plane cuts it (here, past the view's right edge); one with
// an end behind the eye is skipped whole.
TEST_F(RendererTest, PolylineThroughTheNearPlaneDrawsItsVisiblePart) {
  DrawList list;
  list.width = 160;
  list.height = 120;
  const View v = cameraView(160, 120);  // eye at z = 5, near plane 0.1 in front of it
  list.views = {v};
  PolylineItem reaching;
  reaching.points = {{-1.0f, 0.0f, 0.0f}, {0.3f, 0.0f, 4.95f}};  // 0.05 in front of the eye
  reaching.color = {1, 1, 1, 1};
  reaching.widthPx = 6.0f;
  PolylineItem behind = reaching;
  behind.points = {{-1.0f, 0.5f, 0.0f}, {0.3f, 0.5f, 6.0f}};
  list.polylines = {reaching, behind};
  const media::Image img = renderer_->render(list);
  const glm::mat4 clipFromWorld = v.camera.clipFromView * v.camera.viewFromWorld;
  auto pixelOf = [&](glm::vec3 world) {
    const glm::vec4 c = clipFromWorld * glm::vec4(world, 1.0f);
    return glm::ivec2(int((c.x / c.w * 0.5f + 0.5f) * float(v.width)),
                      int((0.5f - c.y / c.w * 0.5f) * float(v.height)));
  };
  const glm::ivec2 start = pixelOf(reaching.points[0]);
  for (int x = start.x + 4; x < v.width; ++x) EXPECT_EQ(img.pixel(x, start.y)[0], 255) << "x = " << x;
  EXPECT_EQ(img.pixel(start.x - 6, start.y)[0], 0);  // beyond the round cap
  const glm::ivec2 skipped = pixelOf(behind.points[0]);
  for (int x = skipped.x - 4; x <= skipped.x + 4; ++x) EXPECT_EQ(img.pixel(x, skipped.y)[0], 0) << "x = " << x;
}

}  // namespace
}  // namespace rollspin::render
