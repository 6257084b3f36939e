// The view pass (view_pass.hpp): a view's steps over a frame, in order.
#include "render/view_pass.hpp"

#include <algorithm>

#include "render/coverage_edges.hpp"
#include "render/layer_plan.hpp"
#include "render/screen_bounds.hpp"

namespace rollspin::render {

// Binds the scene (or `fbo`), the view's viewport and shadow map, scissored
// to `clip` (image pixels, top-left origin; the view's own rectangle if
// null); the scope of the draws that follow.
DrawScope beginView(const FrameTargets& targets, const DrawList& list, const View& v, const ViewItems& viewItems,
                    const PixelRect* clip, GLuint fbo) {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo != 0 ? fbo : GLuint(targets.sceneFbo));
  DrawScope scope;
  scope.samples = fbo != 0 && fbo == targets.opaqueFbo ? targets.samples : 1;
  const int glY = list.height - v.y - v.height;  // GL counts rows from the bottom
  glViewport(v.x, glY, v.width, v.height);
  glEnable(GL_SCISSOR_TEST);
  const PixelRect r = clip != nullptr ? *clip : PixelRect{v.x, v.y, v.x + v.width, v.y + v.height};
  glScissor(r.x0, list.height - r.y1, r.x1 - r.x0, r.y1 - r.y0);
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDepthMask(GL_TRUE);
  scope.view = &v;
  scope.clipFromWorld = v.camera.clipFromView * v.camera.viewFromWorld;
  scope.shadow = viewItems.shadow;
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, viewItems.shadowMap != nullptr ? GLuint(viewItems.shadowMap->texture) : 0u);
  return scope;
}

// The tiles of view v (inside its rectangle) where the opaque meshes drawn
// in samples (`which` of them) can cover a pixel in part, so where their
// samples are drawn and resolved: near a static mesh's outline or cuts
// (coverage_edges.hpp), where two static meshes' boxes meet (their
// intersection is no edge of either), and all over a moving one's bounds
// (an arrow: the same tiles redrawSamples redraws over a layer).
// A surface that intersects itself gets no samples along the crossing.
std::vector<PixelRect> sampleTiles(GpuCaches& caches, const FrameTargets& targets, const DrawList& list, const View& v,
                                   const ViewItems& viewItems, Items which) {
  TileGrid grid(list.width, list.height);
  const glm::mat4 clipFromWorld = v.camera.clipFromView * v.camera.viewFromWorld;
  std::vector<PixelRect> bounds;
  std::vector<std::pair<glm::vec3, glm::vec3>> boxes;  // the static meshes' world boxes
  for (const Drawable& d : viewItems.items) {
    if (d.material->opacity < 1.0f || !MeshPass::inSamplesPass(d, targets) || !takes(which, d.dynamic)) continue;
    if (d.dynamic) {
      bounds.clear();
      meshBounds(caches, v, clipFromWorld, d, bounds);
      for (const PixelRect& r : bounds) grid.add(r);
      continue;
    }
    addOutlineTiles(*d.mesh, caches.edges(d.mesh), d.worldFromModel, d.material->cutPlane, v, 2.0f, grid);
    const GpuMesh& g = caches.mesh(d.mesh);
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const glm::vec3& corner : boxCorners(g.lo, g.hi, d.worldFromModel)) {
      lo = glm::min(lo, corner);
      hi = glm::max(hi, corner);
    }
    boxes.emplace_back(lo, hi);
  }
  for (std::size_t a = 0; a < boxes.size(); ++a)
    for (std::size_t b = a + 1; b < boxes.size(); ++b) {
      const glm::vec3 lo = glm::max(boxes[a].first, boxes[b].first), hi = glm::min(boxes[a].second, boxes[b].second);
      if (lo.x > hi.x || lo.y > hi.y || lo.z > hi.z) continue;
      grid.add(screenBounds(v, clipFromWorld, boxCorners(lo, hi).data(), 8, 2.0f));
    }
  const PixelRect area{v.x, v.y, v.x + v.width, v.y + v.height};
  std::vector<PixelRect> tiles;
  for (const PixelRect& r : grid.rects())
    if (const PixelRect inside = intersect(r, area); !inside.empty()) tiles.push_back(inside);
  return tiles;
}

// A mesh's screen bounds, as rectangles that together hold it: the
// corners of its model-space bounding box, narrowed to its bounding
// sphere's projection (a ball's box projects to a square about 1.5 times
// its outline). A long thin mesh (an arrow's shaft) is cut across its
// length into slabs of about its width, each bounded alone: a diagonal
// arrow dirties a band along itself, not the square it spans.
void meshBounds(GpuCaches& caches, const View& v, const glm::mat4& clipFromWorld, const Drawable& d,
                std::vector<PixelRect>& out) {
  const GpuMesh& g = caches.mesh(d.mesh);
  const glm::mat3 linear(d.worldFromModel);
  const glm::vec3 extent =
      (g.hi - g.lo) * glm::vec3(glm::length(linear[0]), glm::length(linear[1]), glm::length(linear[2]));
  int along = 0;
  for (int a = 1; a < 3; ++a)
    if (extent[a] > extent[along]) along = a;
  const float across = std::max(extent[(along + 1) % 3], extent[(along + 2) % 3]);
  const int slabs = across > 0.0f ? std::clamp(int(std::ceil(extent[along] / across)), 1, 16) : 1;
  const float scale = std::max({glm::length(linear[0]), glm::length(linear[1]), glm::length(linear[2])});
  const glm::vec3 centre(d.worldFromModel * glm::vec4(glm::vec3(g.bound), 1.0f));
  const std::optional<PixelRect> sphere = sphereBounds(v, centre, g.bound.w * scale, 2.0f);
  for (int slab = 0; slab < slabs; ++slab) {
    glm::vec3 lo = g.lo, hi = g.hi;
    lo[along] = g.lo[along] + (g.hi[along] - g.lo[along]) * float(slab) / float(slabs);
    hi[along] =
        slab + 1 == slabs ? g.hi[along] : g.lo[along] + (g.hi[along] - g.lo[along]) * float(slab + 1) / float(slabs);
    const PixelRect box = screenBounds(v, clipFromWorld, boxCorners(lo, hi, d.worldFromModel).data(), 8, 2.0f);
    out.push_back(sphere ? intersect(box, *sphere) : box);
  }
}

// A view's opaque meshes drawn whole (in a frame drawn whole, or a fresh
// view): at one sample, then in samples tile rectangle by tile rectangle
// of sampleTiles, resolved over them. `clear`: the view's rectangle is cleared
// first, scissored (an inset, a fresh view); otherwise the frame's one
// clear did it. llvmpipe pays for samples (a clear, a draw and a resolve
// of four values a pixel) only near edges: a 1080p frame whose camera
// moves drew its ball view's floor in samples in full.
// Returns the tiles drawn in samples: the only pixels that the meshes
// cover in part (alpha strictly between 0 and 1).
std::vector<PixelRect> drawViewOpaque(const ViewDrawing& drawing, const DrawList& list, const View& v,
                                      const ViewItems& viewItems, bool clear, std::vector<PixelRect>* under) {
  const FrameTargets& targets = drawing.targets;
  DrawScope scope = beginView(targets, list, v, viewItems, nullptr);
  scope.under = under;
  if (clear) {
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClear(GL_DEPTH_BUFFER_BIT | GL_COLOR_BUFFER_BIT);
  }
  drawing.meshes.drawOpaqueAtCentres(viewItems, scope, Items::StaticOnly, drawing.meshDrawing());
  drawing.meshes.drawOpaqueAtCentres(viewItems, scope, Items::DynamicOnly, drawing.meshDrawing());
  if (targets.opaqueFbo == 0) return {};
  const std::vector<PixelRect> tiles = sampleTiles(drawing.caches, targets, list, v, viewItems, Items::All);
  drawing.stats.wholeViewPixels += static_cast<long long>(v.width) * v.height;
  for (const PixelRect& r : tiles) drawing.stats.sampledPixels += static_cast<long long>(r.x1 - r.x0) * (r.y1 - r.y0);
  // Each tile rectangle drawn in a box of its own, a pixel wider than it:
  // a multisampled pixel on a scissor's edge can lose samples, and those
  // it keeps are shaded at their centroid, off the pixel's (seen: one
  // pixel in a 1080p frame differed from a draw without a scissor, on a
  // box's top row). Islands (see redrawRects) would merge the tiles along
  // a long diagonal edge into the box it spans. So the boxes go in
  // rounds: no box of a round reaches another rectangle of it, and a
  // round's rectangles are resolved before the next round's boxes (which
  // can reach them) are cleared and drawn. Rectangles that touch are in
  // different rounds; two to four rounds in practice.
  const PixelRect area{v.x, v.y, v.x + v.width, v.y + v.height};
  std::vector<PixelRect> boxes;
  for (const PixelRect& r : tiles) boxes.push_back(intersect(PixelRect{r.x0 - 1, r.y0 - 1, r.x1 + 1, r.y1 + 1}, area));
  std::vector<int> roundOf(tiles.size(), 0);
  int rounds = 0;
  for (std::size_t i = 0; i < tiles.size(); ++i) {
    std::vector<bool> taken(static_cast<std::size_t>(rounds) + 1, false);
    for (std::size_t j = 0; j < i; ++j)
      if (overlaps(boxes[i], tiles[j])) taken[static_cast<std::size_t>(roundOf[j])] = true;
    while (taken[static_cast<std::size_t>(roundOf[i])]) ++roundOf[i];
    rounds = std::max(rounds, roundOf[i] + 1);
  }
  std::vector<PixelRect> oneBox(1);
  glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  for (int round = 0; round < rounds; ++round) {
    for (std::size_t i = 0; i < tiles.size(); ++i) {
      if (roundOf[i] != round) continue;
      oneBox[0] = boxes[i];
      (void)beginView(targets, list, v, viewItems, &oneBox[0], targets.opaqueFbo);
      glClear(GL_DEPTH_BUFFER_BIT | GL_COLOR_BUFFER_BIT);
    }
    for (std::size_t i = 0; i < tiles.size(); ++i) {
      if (roundOf[i] != round) continue;
      oneBox[0] = boxes[i];
      DrawScope inBox = beginView(targets, list, v, viewItems, &oneBox[0], targets.opaqueFbo);
      inBox.clips = &oneBox;
      inBox.under = under;
      drawing.meshes.drawOpaque(viewItems, inBox, Items::StaticOnly, Pass::Samples, drawing.meshDrawing());
      drawing.meshes.drawOpaque(viewItems, inBox, Items::DynamicOnly, Pass::Samples, drawing.meshDrawing());
    }
    for (std::size_t i = 0; i < tiles.size(); ++i)
      if (roundOf[i] == round) drawing.targets.resolve(list, tiles[i], drawing.programs, drawing.streams);
  }
  return tiles;
}

// After drawViewOpaque: the steps at one sample, a ray-cast sphere's
// under pass only where the meshes cover pixels in part (`sampled`) or a
// sphere drawn before it does (the pass changes nothing elsewhere: see
// SpherePass::draw), then the rest.
void drawViewAfterOpaque(const ViewDrawing& drawing, const DrawList& list, int view, const ViewItems& viewItems,
                         std::vector<PixelRect> sampled, const DrawScope& scope) {
  DrawScope afterResolve = scope;
  afterResolve.under = &sampled;
  drawAfterResolve(drawing, viewItems, afterResolve);
  drawRest(drawing, list, view, viewItems, Items::All, scope);
}

// What a frame draws at one sample after the resolve, before drawRest.
void drawAfterResolve(const ViewDrawing& drawing, const ViewItems& viewItems, const DrawScope& scope) {
  drawing.meshes.drawReshades(viewItems, scope, drawing.meshDrawing());
  drawing.meshes.drawOpaque(viewItems, scope, Items::DynamicOnly, Pass::Coverage, drawing.meshDrawing());
}

// Everything after the opaque meshes and the re-shade: depth-tested lines,
// translucent meshes far to near, then lines over everything, labels and
// the inset frame.
void drawRest(const ViewDrawing& drawing, const DrawList& list, int index, const ViewItems& viewItems, Items which,
              const DrawScope& scope) {
  const View& v = list.views[static_cast<std::size_t>(index)];
  const glm::mat4 clipFromWorld = v.camera.clipFromView * v.camera.viewFromWorld;
  // A line's quad faces either way: no culling, whatever ran before (the
  // shadow pass culls, and a layer's update draws no opaque mesh first).
  glDisable(GL_CULL_FACE);
  glDepthMask(GL_FALSE);
  glEnable(GL_BLEND);
  for (const PolylineItem& p : list.polylines)
    if (p.view == index && p.depthTested && takes(which, p.dynamic))
      drawing.lines.draw(p, scope, drawing.programs.line, drawing.streams, drawing.targets.height, drawing.stats);

  // Far to near. A closed translucent mesh shows its front half only: its
  // back half would double the blending cost for little visual gain.
  std::vector<const Drawable*> translucent;
  for (const Drawable& d : viewItems.items)
    if (d.material->opacity < 1.0f && takes(which, d.dynamic)) translucent.push_back(&d);
  auto depthOf = [&](const Drawable* d) { return (v.camera.viewFromWorld * d->worldFromModel[3]).z; };
  std::stable_sort(translucent.begin(), translucent.end(),
                   [&](const Drawable* a, const Drawable* b) { return depthOf(a) < depthOf(b); });
  {
    const ClipDistances clipped;
    // Translucent layers (glass, the Bloch sphere) take no shadow.
    for (const Drawable* d : translucent)
      drawing.meshes.draw(*d, scope, false, d->material->cull, drawing.meshDrawing());
  }
  glDisable(GL_CULL_FACE);
  glDisable(GL_DEPTH_TEST);
  for (const PolylineItem& p : list.polylines)
    if (p.view == index && !p.depthTested && takes(which, p.dynamic))
      drawing.lines.draw(p, scope, drawing.programs.line, drawing.streams, drawing.targets.height, drawing.stats);
  for (const LabelItem& l : list.labels)
    if (l.view == index)
      drawLabelAs(l, which, glm::vec2(v.width, v.height), &clipFromWorld, scope, drawing.textDrawing());
  if (v.frame && which != Items::DynamicOnly) {
    const float w = float(v.width), h = float(v.height), t = std::max(1.0f, h / 300.0f);
    const std::vector<GlyphQuad> border{
        {0, 0, w, t, 0, 0, 0, 0}, {0, h - t, w, h, 0, 0, 0, 0}, {0, 0, t, h, 0, 0, 0, 0}, {w - t, 0, w, h, 0, 0, 0, 0}};
    drawQuads(border, glm::vec2(w, h), glm::vec4(0.35f, 0.38f, 0.42f, 1.0f), 0, true, drawing.textDrawing());
  }
  glDepthMask(GL_TRUE);
}

// The whole frame, as the static items' layer and dynamic items would
// draw it, step for step (see retained_layers.cpp).
void drawWhole(const ViewDrawing& drawing, const DrawList& list, const std::vector<ViewItems>& perView) {
  for (std::size_t i = 0; i < list.views.size(); ++i) {
    const View& v = list.views[i];
    bool overlapsEarlier = false;
    for (std::size_t j = 0; j < i; ++j) overlapsEarlier = overlapsEarlier || viewsOverlap(list.views[i], list.views[j]);
    // An inset over a view drawn before clears its own rectangle (a
    // scissored clear is a full-screen quad on llvmpipe: only an inset
    // pays for it).
    std::vector<PixelRect> sampled = drawViewOpaque(drawing, list, v, perView[i], overlapsEarlier, nullptr);
    const DrawScope scope = beginView(drawing.targets, list, v, perView[i], nullptr);
    drawViewAfterOpaque(drawing, list, static_cast<int>(i), perView[i], std::move(sampled), scope);
  }
  drawImageLabels(list, Items::All, PixelRect{0, 0, list.width, list.height}, drawing.targets.sceneFbo,
                  drawing.textDrawing());
}

}  // namespace rollspin::render
