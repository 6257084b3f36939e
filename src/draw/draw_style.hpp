// The drawing's shared look: the palette (linear RGB), the body text size,
// the glass material, and the Eigen → glm conversions every view uses.
#pragma once

#include <algorithm>
#include <numbers>

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
