// The sphere pass: a sphere drawn at one sample is ray-cast (mesh.frag with
// IMPOSTOR), shaded per pixel in the bands of its screen rectangle that its
// silhouette reaches; a translucent one over a retained layer is replayed
// from its capture (glass_capture.hpp). Renderer-internal.
#pragma once

#include <vector>

#include "render/draw_scope.hpp"
#include "render/gl_objects.hpp"
#include "render/glass_capture.hpp"
#include "render/programs.hpp"
#include "render/renderer.hpp"

namespace rollspin::render {

// What a ray-cast sphere is drawn with: the programs (its under pass's),
// the vertex streams, the translucent spheres' captures, the counters, and
// the framebuffer's size in pixels.
struct SphereDrawing {
  Programs& programs;
  const VertexStreams& streams;
  SphereCaptures& captures;
  RenderStats& stats;
  int fbWidth, fbHeight;
};

// Draws ray-cast spheres; holds the parts it reuses from draw to draw (no
// allocation per draw).
class SpherePass {
 public:
  // The sphere `d` in its screen rectangle `rect` of scope's view, with the
  // program `mesh` (in use, its uniforms set) and the pattern it uses;
  // `shadowed`: it samples the shadow map (never replayed).
  void draw(const Drawable& d, const DrawScope& scope, Program& mesh, const PixelRect& rect, int pattern, bool shadowed,
            const SphereDrawing& with);

 private:
  // The parts of a translucent sphere from its capture (glass_capture.cpp).
  void replayCaptured(const Drawable& d, const DrawScope& scope, const PixelRect& rect, int pattern,
                      const glm::mat4& worldFromClip, const glm::vec4& viewport, const SphereDrawing& with);

  std::vector<PixelRect> parts_;       // the bands inside the rectangles drawn
  std::vector<PixelRect> underParts_;  // parts_ inside one rectangle of scope.under
  std::vector<glm::vec3> replayCorners_;
};

// One triangle of impostor.vert per rectangle, each scissored to it inside
// the scissor in force, in a framebuffer fbWidth × fbHeight.
void drawImpostorParts(Program& program, const View& v, const std::vector<PixelRect>& rects, int fbWidth, int fbHeight);

}  // namespace rollspin::render
