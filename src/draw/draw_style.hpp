// The drawing's shared look: the palette (linear RGB), the body text size,
// the glass material, and the Eigen → glm conversions every view uses.
#pragma once

#include <algorithm>
#include <cstddef>
#include <numbers>
#include <utility>

#include <glm/glm.hpp>

#include "geometry/surface.hpp"
#include "render/draw_list.hpp"
#include "spin/su2.hpp"

namespace rollspin::draw {

inline constexpr double kDeg = std::numbers::pi / 180.0;

// The palette: muted surfaces, saturated actors (linear RGB).
inline const glm::vec3 kMarkerColor{0.80f, 0.04f, 0.03f};
inline const glm::vec3 kFieldColor{0.03f, 0.22f, 0.78f};
inline const glm::vec4 kPathColor{0.10f, 0.16f, 0.32f, 0.55f};
inline const glm::vec4 kTravelledColor{0.95f, 0.33f, 0.02f, 1.0f};
inline const glm::vec4 kTextColor{0.04f, 0.05f, 0.07f, 1.0f};

// Lines are opaque: a polyline's segments overlap at the joints (each is a
// capsule, round at both ends), and a translucent line blended twice there
// shows a darker bead at every joint. The colour is the translucent one
// premixed over the light grey most lines cross.
inline glm::vec4 opaqueLine(const glm::vec3& color, float alpha) {
  return glm::vec4(glm::mix(glm::vec3(0.78f, 0.79f, 0.80f), color, alpha), 1.0f);
}
inline const glm::vec4 kPathLineColor = opaqueLine(glm::vec3(kPathColor), kPathColor.a);
inline const glm::vec4 kMarkerTrailColor = opaqueLine(kMarkerColor, 0.55f);
inline const glm::vec3 kPlateColor{0.35f, 0.10f, 0.55f};
inline const glm::vec4 kPlateTrailColor = opaqueLine(kPlateColor, 0.7f);
inline const glm::vec4 kBlochTrailColor = opaqueLine(kMarkerColor, 0.85f);
inline const glm::vec4 kFieldTrailColor = opaqueLine(kFieldColor, 0.7f);

// A line that grows with s (a trail, the travelled path) whose points are a
// prefix of one fixed grid plus the current point. It is drawn as two lines:
// the points settled at the last of kGrowingLineCheckpoints fixed grid
// indices, static (a retained layer keeps them until the next checkpoint,
// instead of redrawing the whole line every frame), and the rest from that
// point on, dynamic. Lines are opaque and cover samples by distance alone,
// so the two draw exactly the samples the one line would. 64: every frame
// redraws the dynamic rest, and an update of the layer redraws only the new
// prefix's tiles, so settling often is cheap (a 10 s 1080p lollipop clip in
// order: 27.8–29.6 ms of CPU a frame with 8, 25.6–26.0 with 64 or 128, at
// 0.42 layer updates a frame with 64; bench_render BM_ClipFrames1080p/0/300).
inline constexpr std::size_t kGrowingLineCheckpoints = 64;

// How many leading points are settled: `pointsOnGrid` points of the line lie
// on a grid of `gridCount`; the settled prefix ends on a checkpoint index.
inline std::size_t settledPoints(std::size_t pointsOnGrid, std::size_t gridCount) {
  // Rounded up: at most kGrowingLineCheckpoints prefixes over the grid.
  const std::size_t step =
      std::max<std::size_t>(2, (gridCount + kGrowingLineCheckpoints - 1) / kGrowingLineCheckpoints);
  if (pointsOnGrid < 1) return 0;
  return ((pointsOnGrid - 1) / step) * step + 1;
}

// Appends `line` (flagged dynamic) as its settled static prefix of
// `settled` points and the dynamic rest, which starts on the prefix's last
// point so that the two join.
inline void addGrowingLine(render::DrawList& list, render::PolylineItem line, std::size_t settled) {
  line.dynamic = true;
  settled = std::min(settled, line.points.size());
  if (settled >= 2) {
    render::PolylineItem prefix = line;
    prefix.dynamic = false;
    prefix.points.resize(settled);
    list.polylines.push_back(std::move(prefix));
    line.points.erase(line.points.begin(), line.points.begin() + static_cast<std::ptrdiff_t>(settled - 1));
    if (line.points.size() < 2) return;
  }
  list.polylines.push_back(std::move(line));
}

inline glm::vec3 toGlm(const geometry::Vec3& v) { return {float(v.x()), float(v.y()), float(v.z())}; }

// worldFromBody as a glm matrix (the rotation of U).
inline glm::mat4 rotationOf(const spin::Su2& q) {
  const spin::Mat3 r = q.rotationMatrix();
  glm::mat4 m(1.0f);
  for (int c = 0; c < 3; ++c)
    for (int row = 0; row < 3; ++row) m[c][row] = float(r(row, c));
  return m;
}

// Body text size (em) in pixels for an image `imageHeight` pixels high:
// with the 1.4 em line step a body line takes 1/25.7 of the height (the
// lecture-hall rule asks ≥ 1/28), the same look at 480p, 1080p and 4K;
// render.font_scale multiplies it. A portrait image keeps to the rule with
// the least that meets it (a line 1/27.9 of the height): its width holds
// ~40 characters at that size, and the narrow layout (compactText) prints
// fewer, shorter lines.
inline float bodyTextPx(int imageWidth, int imageHeight, double fontScale = 1.0) {
  const float perLine = imageHeight > imageWidth ? 39.0f : 36.0f;
  return std::max(11.0f, float(imageHeight) / perLine * float(fontScale));
}

// A portrait frame prints fewer, shorter lines: the running angles before
// the arc length, the legend's two entries side by side on one line.
inline bool compactText(int imageWidth, int imageHeight) { return imageHeight > imageWidth; }

// A clear, shiny, shadowless sheet (Brockett's plate, the Bloch sphere).
inline render::Material glassMaterial(const glm::vec3& tint, float opacity, float specular, float shininess) {
  render::Material glass;
  glass.color = tint;
  glass.opacity = opacity;
  glass.specular = specular;
  glass.shininess = shininess;
  glass.castsShadow = false;
  return glass;
}

}  // namespace rollspin::draw
