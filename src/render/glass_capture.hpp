// The glass capture: a translucent ray-cast sphere's fragments depend on the
// pixel's position and on uniforms alone (see mesh.frag's castSphere):
// captured once over its screen rectangle (the colour mesh.frag gives each
// pixel, before blending, and its depth), they are replayed in later frames
// (sphere_replay.frag, SpherePass::replayCaptured) with the same values,
// so blending and the depth test give the same bytes. A frame over the
// retained layer then fetches two texels a pixel instead of casting the ray
// and lighting it. Renderer-internal.
#pragma once

#include <deque>

#include "render/draw_scope.hpp"
#include "render/programs.hpp"
#include "render/renderer.hpp"

namespace rollspin::render {

// What a sphere's fragments depend on (the unshadowed program reads no more).
struct SphereInputs {
  glm::mat4 worldFromModel, clipFromWorld;
  glm::vec3 towardLight, lightColor, cameraPosition;
  float ambient;
  glm::vec4 viewport;
  PixelRect rect;
  Material material;
  bool operator==(const SphereInputs&) const = default;
};

struct SphereCapture {
  SphereInputs inputs;
  GlObject fbo, color, depth;
  int originX = 0, originY = 0;  // the window pixel (GL, from the bottom) of texel (0, 0)
};

class SphereCaptures {
 public:
  // The capture of the unshadowed translucent sphere `d` drawn in `rect`
  // in `scope`, made now if none matches (see glass_capture.cpp).
  const SphereCapture& of(const Drawable& d, const PixelRect& rect, int pattern, const glm::mat4& worldFromClip,
                          const glm::vec4& viewport, const DrawScope& scope, int fbHeight, Programs& programs,
                          RenderStats& stats);
  // No layer (a camera move, most likely, which they would not survive),
  // or new framebuffers.
  void clear() { captures_.clear(); }

 private:
  static constexpr std::size_t kKept = 4;
  std::deque<SphereCapture> captures_;  // the newest last
};

}  // namespace rollspin::render
