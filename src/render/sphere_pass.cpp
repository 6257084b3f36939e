// Ray-cast spheres (mesh.frag with IMPOSTOR): a sphere drawn at one sample
// is shaded per pixel in the bands of its screen rectangle that its
// silhouette reaches, its coverage blended over what is behind, with depth
// per pixel; an opaque one first adds itself under the edges of what is
// drawn (the under pass). A translucent one over a retained layer is
// replayed from its capture (glass_capture.cpp).
#include "render/sphere_pass.hpp"

#include <algorithm>

namespace rollspin::render {

namespace {

// The non-empty parts of `rects` inside `box`, into `out`.
void clippedParts(const std::vector<PixelRect>& rects, const PixelRect& box, std::vector<PixelRect>& out) {
  out.clear();
  for (const PixelRect& r : rects)
    if (const PixelRect p = intersect(r, box); !p.empty()) out.push_back(p);
}

}  // namespace

glm::vec4 ndcRectOf(const View& v, const PixelRect& rect) {
  return glm::vec4(
      2.0f * float(rect.x0 - v.x) / float(v.width) - 1.0f, 1.0f - 2.0f * float(rect.y1 - v.y) / float(v.height),
      2.0f * float(rect.x1 - v.x) / float(v.width) - 1.0f, 1.0f - 2.0f * float(rect.y0 - v.y) / float(v.height));
}

void SpherePass::draw(const Drawable& d, const DrawScope& scope, Program& mesh, const PixelRect& rect, int pattern,
                      bool shadowed, const SphereDrawing& with) {
  const View& v = *scope.view;
  const Material& m = *d.material;
  const bool opaque = m.opacity >= 1.0f;
  // Only the rectangle's bands that the silhouette reaches (its corners,
  // a fifth of it, are all outside), and over a retained layer only their
  // parts inside the rectangles being redrawn: an island's scissor box
  // reaches pixels outside them, which are neither composited nor read
  // back, and a large sphere (the Bloch sphere's glass) would be shaded
  // over all of them. Each pixel is shaded as the whole rectangle shades
  // it (the shader depends on the pixel's position alone).
  const float radius = glm::length(glm::vec3(d.worldFromModel[0]));
  const std::vector<PixelRect> bands =
      sphereBands(v, rect, glm::vec3(d.worldFromModel[3]), radius, kImpostorMarginPx, kImpostorBandRows);
  std::vector<PixelRect>& parts = parts_;
  parts.clear();
  for (const PixelRect& band : bands) {
    if (scope.clips == nullptr) {
      parts.push_back(band);
      continue;
    }
    for (const PixelRect& clip : *scope.clips)
      if (const PixelRect p = intersect(band, clip); !p.empty()) parts.push_back(p);
  }
  if (parts.empty()) return;
  const glm::mat4 worldFromClip = glm::inverse(scope.clipFromWorld);
  const int fbHeight = with.fbHeight;
  const glm::vec4 viewport(float(v.x), float(fbHeight - v.y - v.height), float(v.width), float(v.height));
  // Opaque meshes are drawn without blending (drawOpaque): on for this one.
  glEnable(GL_BLEND);
  glDisable(GL_CULL_FACE);
  glBindVertexArray(with.streams.empty);
  // Over a retained layer, a translucent sphere that stays there (the
  // Bloch sphere's glass, shaded again in every frame's rectangles over
  // it) is replayed from its capture.
  if (!opaque && !scope.depthOnly && !shadowed && scope.clips != nullptr) {
    replayCaptured(d, scope, rect, pattern, worldFromClip, viewport, with);
    return;
  }
  const bool behindEdges = opaque && !scope.depthOnly;
  if (behindEdges) {
    // Behind what a pixel's centre shows, where that covers the pixel only
    // in part (an edge of a surface, resolved from its samples over
    // transparent black: alpha < 1), the sphere shows through the rest:
    // added under it (premultiplied, weighted by 1 − alpha), as the
    // samples of a whole multisampled frame would have shown it. Drawn
    // first, before the sphere's own edges are there to be drawn under.
    // Its rectangle lies at the sphere's far depth (IMPOSTOR 2 gives no
    // depth of its own): llvmpipe rejects the pixels where the scene is
    // behind the whole sphere before it shades them. Where the scene lies
    // within the sphere's depth, the pass adds it under what is there
    // (alpha 1 away from edges: nothing changes), and the sphere, in
    // front there, is drawn over it next. Over a retained layer only
    // where such pixels can be (scope.under): elsewhere alpha is 1 or
    // the depth is the clear value, and the pass would change nothing.
    Program& under = with.programs.mesh(pattern, false, m.lit, m.specular > 0.0f, 2);
    under.use();
    setMeshUniforms(under, d, scope, false);
    under.set("worldFromClip", worldFromClip);
    under.set("viewportRect", viewport);
    const glm::vec4 centre = v.camera.viewFromWorld * d.worldFromModel[3];
    const glm::vec4 far = v.camera.clipFromView * (centre - glm::vec4(0.0f, 0.0f, radius, 0.0f));
    under.set("ndcDepth", std::clamp(far.z / far.w, -1.0f, 1.0f));
    glDepthFunc(GL_GREATER);
    glDepthMask(GL_FALSE);
    glBlendFuncSeparate(GL_ONE_MINUS_DST_ALPHA, GL_ONE, GL_ONE_MINUS_DST_ALPHA, GL_ONE);
    if (scope.under == nullptr) {
      drawImpostorParts(under, v, parts, with.fbWidth, with.fbHeight);
    } else {
      for (const PixelRect& part : *scope.under) {
        clippedParts(parts, part, underParts_);
        drawImpostorParts(under, v, underParts_, with.fbWidth, with.fbHeight);
      }
    }
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LEQUAL);
    mesh.use();
  }
  mesh.set("worldFromClip", worldFromClip);
  mesh.set("viewportRect", viewport);
  mesh.set("ndcDepth", 0.0f);
  drawImpostorParts(mesh, v, parts, with.fbWidth, with.fbHeight);
  if (behindEdges && scope.under != nullptr) scope.under->push_back(rect);  // its edges, for a sphere drawn after it
  if (opaque) glDisable(GL_BLEND);
}

// One triangle of impostor.vert per part (disjoint: blending draws each
// pixel once), scissored to the part inside the scissor in force: a
// rectangle's two triangles would both shade the pixel blocks along
// their diagonal (llvmpipe shades a block that a triangle covers in part
// whole, under a mask), and a band is little more than that diagonal.
void drawImpostorParts(Program& program, const View& v, const std::vector<PixelRect>& rects, int fbWidth,
                       int fbHeight) {
  GLint box[4] = {0, 0, fbWidth, fbHeight};
  const bool scissored = glIsEnabled(GL_SCISSOR_TEST) == GL_TRUE;
  if (scissored) glGetIntegerv(GL_SCISSOR_BOX, box);
  const PixelRect inForce{box[0], fbHeight - box[1] - box[3], box[0] + box[2], fbHeight - box[1]};
  glEnable(GL_SCISSOR_TEST);
  for (const PixelRect& r : rects) {
    const PixelRect part = intersect(r, inForce);
    if (part.empty()) continue;
    glScissor(part.x0, fbHeight - part.y1, part.x1 - part.x0, part.y1 - part.y0);
    program.set("ndcRect", ndcRectOf(v, part));
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }
  glScissor(box[0], box[1], box[2], box[3]);
  if (!scissored) glDisable(GL_SCISSOR_TEST);
}

}  // namespace rollspin::render
