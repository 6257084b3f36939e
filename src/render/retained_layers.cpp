// ---- Retained layers ----------------------------------------------------
//
// A frame is drawn in this order, view by view. The static opaque
// meshes, then the moving opaque meshes that are not spheres (arrows), at
// one sample into the scene (its colour where no pixel is covered in
// part, the depth at the pixel centres everywhere), and in samples
// (opaqueFbo, msaa of them) in the tiles near their edges and over the
// arrows, resolved there over the scene (see drawViewOpaque). Then at one
// sample, each step antialiased by its own coverage: the receivers'
// re-shade inside the shadow box; the moving spheres, ray-cast;
// depth-tested lines; translucent meshes; overlays (see drawRest). So
// llvmpipe pays for the samples only near edges, and over a layer only
// over the arrows.
// When the static items and the views are the same as in the frame
// before, the renderer keeps (a) the scene after the static opaque meshes
// (colour and depth, one sample, and their samples too) and (b) the
// finished image of the static items alone. A frame then starts from (b)
// and redraws only the rectangles that its dynamic items (and the shadow
// box) can touch: (a) copied in, the arrows' tiles drawn over its samples
// and resolved, then every later step, scissored. Outside those
// rectangles a whole frame draws exactly what (b) holds, and inside them
// exactly the same steps run on the same values, so both ways give the
// same bytes: a frame does not depend on the frames before it (tested),
// and the first frame of a span is simply drawn whole.
// The retained layer: (a) in the targets' snapshot framebuffers, (b) in
// RetainedLayer's image; valid while its memory's layerKey matches
// (layer_plan.hpp).
#include "render/retained_layers.hpp"

#include <algorithm>
#include <cstring>
#include <functional>

#include "render/screen_bounds.hpp"
#include "render/text_pass.hpp"

namespace rollspin::render {

namespace {

// The parts of `r` outside `hole`, appended to `out` (disjoint, at most four).
void outside(const PixelRect& r, const PixelRect& hole, std::vector<PixelRect>& out) {
  const PixelRect h = intersect(r, hole);
  if (h.empty()) {
    out.push_back(r);
    return;
  }
  for (const PixelRect& p : {PixelRect{r.x0, r.y0, r.x1, h.y0}, PixelRect{r.x0, h.y1, r.x1, r.y1},
                             PixelRect{r.x0, h.y0, h.x0, h.y1}, PixelRect{h.x1, h.y0, r.x1, h.y1}})
    if (!p.empty()) out.push_back(p);
}

// `rects` less the rectangles of the fresh views (drawn whole).
void outsideFreshViews(const DrawList& list, const std::vector<bool>& fresh, std::vector<PixelRect>& rects,
                       std::vector<PixelRect>& scratch) {
  for (std::size_t i = 0; i < list.views.size(); ++i) {
    if (!fresh[i]) continue;
    const View& v = list.views[i];
    scratch.clear();
    for (const PixelRect& r : rects) outside(r, PixelRect{v.x, v.y, v.x + v.width, v.y + v.height}, scratch);
    std::swap(rects, scratch);
  }
}

// `r` of `from` into `to` (images of one size).
void copyPixels(const media::Image& from, media::Image& to, const PixelRect& r) {
  const std::size_t rowBytes = static_cast<std::size_t>(r.x1 - r.x0) * 4;
  for (int y = r.y0; y < r.y1; ++y) {
    const std::size_t at = (static_cast<std::size_t>(y) * from.width + r.x0) * 4;
    std::memcpy(to.rgba.data() + at, from.rgba.data() + at, rowBytes);
  }
}

// Where a receiver's re-shade can draw: its triangles clipped to the
// shadow box's prism across the light (|x|, |y| ≤ 1 in light clip space,
// affine: an orthographic light), projected.
PixelRect reshadeBounds(const View& v, const glm::mat4& clipFromWorld, const glm::mat4& lightClipFromWorld,
                        const Drawable& d) {
  const MeshData& m = *d.mesh;
  struct P {
    glm::vec3 world;
    glm::vec2 light;
  };
  std::vector<P> verts(m.vertices.size());
  for (std::size_t i = 0; i < verts.size(); ++i) {
    const glm::vec3 w(d.worldFromModel * glm::vec4(m.vertices[i].position, 1.0f));
    verts[i] = {w, glm::vec2(lightClipFromWorld * glm::vec4(w, 1.0f))};
  }
  std::vector<glm::vec3> inside;
  std::vector<P> poly, next;
  for (std::size_t t = 0; t + 2 < m.indices.size(); t += 3) {
    poly = {verts[m.indices[t]], verts[m.indices[t + 1]], verts[m.indices[t + 2]]};
    for (int plane = 0; plane < 4 && !poly.empty(); ++plane) {
      auto dist = [&](const P& p) { return 1.0f + (plane & 1 ? -1.0f : 1.0f) * p.light[plane / 2]; };
      next.clear();
      for (std::size_t i = 0; i < poly.size(); ++i) {
        const P& a = poly[i];
        const P& b = poly[(i + 1) % poly.size()];
        const float da = dist(a), db = dist(b);
        if (da >= 0.0f) next.push_back(a);
        if ((da >= 0.0f) != (db >= 0.0f)) {
          const float f = da / (da - db);
          next.push_back({a.world + f * (b.world - a.world), a.light + f * (b.light - a.light)});
        }
      }
      std::swap(poly, next);
    }
    for (const P& p : poly) inside.push_back(p.world);
  }
  return screenBounds(v, clipFromWorld, inside.data(), inside.size(), 3.0f);
}

// The pixels a frame must redraw over the retained layer, as disjoint
// rectangles of whole tiles: the tiles that any dynamic item (a line
// segment by segment, so that a long trail dirties a thin band along
// itself) or a receiver's shadow box can touch. A fresh view is dirty whole.
std::vector<PixelRect> dirtyRects(GpuCaches& caches, const DrawList& list, const std::vector<ViewItems>& perView,
                                  const std::vector<bool>& fresh) {
  TileGrid grid(list.width, list.height);
  auto add = [&](const PixelRect& rect) { grid.add(rect); };
  std::vector<PixelRect> meshRects;
  for (std::size_t i = 0; i < list.views.size(); ++i) {
    const View& v = list.views[i];
    const int index = static_cast<int>(i);
    if (fresh[i]) {
      add(PixelRect{v.x, v.y, v.x + v.width, v.y + v.height});
      continue;
    }
    const glm::mat4 clipFromWorld = v.camera.clipFromView * v.camera.viewFromWorld;
    for (const Drawable& d : perView[i].items) {
      if (d.dynamic) {
        meshRects.clear();
        meshBounds(caches, v, clipFromWorld, d, meshRects);
        for (const PixelRect& rect : meshRects) add(rect);
      }
      if (perView[i].shadowMap != nullptr && d.material->receivesShadow && d.material->opacity >= 1.0f)
        add(reshadeBounds(v, clipFromWorld, perView[i].shadow.lightClipFromWorld, d));
    }
    for (const PolylineItem& p : list.polylines)
      if (p.view == index && p.dynamic) addSegmentBounds(p, v, clipFromWorld, 0, grid);
    for (const LabelItem& l : list.labels)
      if (l.view == index && l.dynamic) add(labelBounds(l, list, &v, clipFromWorld, caches));
  }
  for (const LabelItem& l : list.labels)
    if (l.view < 0 && l.dynamic) add(labelBounds(l, list, nullptr, glm::mat4(1.0f), caches));
  return grid.rects();
}

// `island(view, island box, scope)` for each view not drawn whole (`fresh`)
// once per island of `rects` in it (separatedIslands), bound on `fbo` (0:
// the scene) and scissored to the island, its meshes, lines and labels
// clipped to the rects (scope.clips); `whole(view)` for a fresh view, in
// the views' order.
template <class Job>
void forEachIsland(const FrameTargets& targets, const Job& job, const std::vector<PixelRect>& rects, GLuint fbo,
                   std::vector<PixelRect>* under,
                   const std::function<void(std::size_t, const PixelRect&, const DrawScope&)>& island,
                   const std::function<void(std::size_t)>& whole = {}) {
  std::vector<PixelRect> islandRects;
  for (std::size_t i = 0; i < job.list.views.size(); ++i) {
    const View& v = job.list.views[i];
    if (job.fresh[i]) {
      if (whole) whole(i);
      continue;
    }
    for (const PixelRect& box : separatedIslands(rects, PixelRect{v.x, v.y, v.x + v.width, v.y + v.height})) {
      islandRects.clear();
      for (const PixelRect& rect : rects)
        if (overlaps(rect, box)) islandRects.push_back(intersect(rect, box));
      DrawScope scope = beginView(targets, job.list, v, job.perView[i], &box, fbo);
      scope.clips = &islandRects;
      scope.under = under;
      island(i, box, scope);
    }
  }
}

// The moving meshes that are drawn in samples (arrows, see Pass), over a
// retained layer, as drawViewOpaque draws them: at one sample over the
// layer's scene, then in samples over the layer's static samples in the
// tiles they reach (sampleTiles), island by island, resolved there. Their
// tiles join `under` (their edges are over the layer's).
template <class Job>
void redrawSamples(const ViewDrawing& drawing, const Job& job, std::vector<PixelRect>* under) {
  const FrameTargets& targets = drawing.targets;
  if (targets.opaqueFbo == 0) return;
  std::vector<PixelRect> reached;  // inside the dirty rectangles: dirtyRects adds the same bounds
  for (std::size_t i = 0; i < job.list.views.size(); ++i) {
    if (job.fresh[i]) continue;
    const std::vector<PixelRect> tiles =
        sampleTiles(drawing.caches, targets, job.list, job.list.views[i], job.perView[i], Items::DynamicOnly);
    reached.insert(reached.end(), tiles.begin(), tiles.end());
  }
  if (reached.empty()) return;
  if (under != nullptr) under->insert(under->end(), reached.begin(), reached.end());
  forEachIsland(targets, job, reached, 0, under, [&](std::size_t i, const PixelRect&, const DrawScope& scope) {
    drawing.meshes.drawOpaqueAtCentres(job.perView[i], scope, Items::DynamicOnly, drawing.meshDrawing());
  });
  FrameTargets::copyRects(job.list, targets.snapshotSamplesFbo, targets.opaqueFbo, reached);
  forEachIsland(
      targets, job, reached, targets.opaqueFbo, under, [&](std::size_t i, const PixelRect&, const DrawScope& scope) {
        drawing.meshes.drawOpaque(job.perView[i], scope, Items::DynamicOnly, Pass::Samples, drawing.meshDrawing());
      });
  for (const PixelRect& rect : reached) drawing.targets.resolve(job.list, rect, drawing.programs, drawing.streams);
}

}  // namespace

// Redraws `rects` (disjoint) of `image` from the snapshot on: the dynamic
// opaque meshes when `which` takes them, then every later step. A fresh
// view (its rectangle among `rects`) is cleared and drawn whole instead,
// exactly as a whole frame draws it, when `which` takes the dynamic items;
// a layer's update leaves it alone.
void RetainedLayer::redrawRects(const ViewDrawing& drawing, Readback& readback, const RedrawJob& job,
                                const std::vector<PixelRect>& rects, Items which, media::Image& image,
                                std::vector<PixelRect>* under) {
  if (rects.empty()) return;
  const DrawList& list = job.list;
  FrameTargets& targets = drawing.targets;
  // The rectangles are disjoint: all copies first, then all draws, so the
  // binned scene is not flushed between them.
  // Unscissored: a blit copies every sample of the rectangle's pixels.
  // Not into a view drawn whole here: the scene is cleared first, with
  // one unscissored clear (a scissored clear of a 1080p view's 1 M pixels
  // is a quad draw: 6–7 ms, with each step finished apart), and those
  // views drawn over it.
  const bool anyFresh =
      which != Items::StaticOnly && std::find(job.fresh.begin(), job.fresh.end(), true) != job.fresh.end();
  if (!anyFresh) {
    FrameTargets::copyRects(list, targets.snapshotFbo, targets.sceneFbo, rects);
  } else {
    targets.clear(list, false);
    std::vector<PixelRect> kept = rects;
    outsideFreshViews(list, job.fresh, kept, splitParts_);
    FrameTargets::copyRects(list, targets.snapshotFbo, targets.sceneFbo, kept);
  }
  if (which != Items::StaticOnly) redrawSamples(drawing, job, under);
  // Then each view drawn once per island of its dirty rectangles (see
  // separatedIslands), scissored to the island's box: the pixels of a box
  // outside the rectangles are drawn over stale samples, but they are
  // neither composited nor read back, and the boxes are disjoint, so each
  // pixel gets the same draws in the same order as in a whole frame. A box
  // reaches a pixel beyond its rectangles (inside the view): llvmpipe tests
  // the scissor per sample, and a multisampled pixel on the scissor's edge
  // seems to lose samples that a whole frame draws (seen, when these steps
  // ran in samples: glass drawn scissor by scissor differed from a whole
  // frame along the row where two met; redrawSamples still draws so).
  PixelRect allBounds{list.width, list.height, 0, 0};
  forEachIsland(
      targets, job, rects, 0, under,
      [&](std::size_t i, const PixelRect& island, const DrawScope& scope) {
        allBounds = unite(allBounds, island);
        if (which != Items::StaticOnly) drawAfterResolve(drawing, job.perView[i], scope);
        drawRest(drawing, list, static_cast<int>(i), job.perView[i], which, scope);
      },
      [&](std::size_t i) {
        if (which == Items::StaticOnly) return;
        const View& v = list.views[i];
        std::vector<PixelRect> sampled =
            drawViewOpaque(drawing, list, v, job.perView[i], false, under);  // cleared with the scene
        DrawScope scope = beginView(targets, list, v, job.perView[i], nullptr);
        scope.under = under;
        drawViewAfterOpaque(drawing, list, static_cast<int>(i), job.perView[i], std::move(sampled), scope);
        allBounds = unite(allBounds, PixelRect{v.x, v.y, v.x + v.width, v.y + v.height});
      });
  for (const PixelRect& rect : rects) allBounds = unite(allBounds, rect);
  drawImageLabels(list, which, allBounds, targets.sceneFbo, drawing.textDrawing());
  for (const PixelRect& rect : rects) readback.pixels(list, image, rect, targets.sceneFbo);
}

// Draws the static items into the scene, keeping the samples after their
// opaque meshes, and reads their finished image into the layer's image.
void RetainedLayer::build(const ViewDrawing& drawing, Readback& readback, const DrawList& list,
                          const std::vector<ViewItems>& perView) {
  FrameTargets& targets = drawing.targets;
  targets.ensureSnapshot();
  targets.clear(list, true);
  if (targets.opaqueFbo != 0) {
    // Every sample, kept for the moving meshes drawn in samples over the
    // layer (redrawSamples), wherever they go.
    for (std::size_t i = 0; i < list.views.size(); ++i) {
      const DrawScope scope = beginView(targets, list, list.views[i], perView[i], nullptr, targets.opaqueFbo);
      drawing.meshes.drawOpaque(perView[i], scope, Items::StaticOnly, Pass::Samples, drawing.meshDrawing());
    }
    glDisable(GL_SCISSOR_TEST);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, targets.opaqueFbo);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, targets.snapshotSamplesFbo);
    glBlitFramebuffer(0, 0, list.width, list.height, 0, 0, list.width, list.height,
                      GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  }
  // The scene as drawViewOpaque draws the static meshes: at one sample,
  // resolved from the samples near their edges.
  std::vector<PixelRect> resolved;
  for (std::size_t i = 0; i < list.views.size(); ++i) {
    const DrawScope scope = beginView(targets, list, list.views[i], perView[i], nullptr);
    drawing.meshes.drawOpaqueAtCentres(perView[i], scope, Items::StaticOnly, drawing.meshDrawing());
    if (targets.opaqueFbo == 0) continue;
    const std::vector<PixelRect> tiles =
        sampleTiles(drawing.caches, targets, list, list.views[i], perView[i], Items::StaticOnly);
    resolved.insert(resolved.end(), tiles.begin(), tiles.end());
  }
  for (const PixelRect& r : resolved) targets.resolve(list, r, drawing.programs, drawing.streams);
  edgeRects_ = partlyCoveredTiles(list, targets.sceneFbo);
  glDisable(GL_SCISSOR_TEST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, targets.sceneFbo);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, targets.snapshotFbo);
  glBlitFramebuffer(0, 0, list.width, list.height, 0, 0, list.width, list.height,
                    GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  for (std::size_t i = 0; i < list.views.size(); ++i) {
    const DrawScope scope = beginView(targets, list, list.views[i], perView[i], nullptr);
    drawRest(drawing, list, static_cast<int>(i), perView[i], Items::StaticOnly, scope);
  }
  drawImageLabels(list, Items::StaticOnly, PixelRect{0, 0, list.width, list.height}, targets.sceneFbo,
                  drawing.textDrawing());
  image_.width = list.width;
  image_.height = list.height;
  image_.rgba.resize(static_cast<std::size_t>(list.width) * list.height * 4);
  readback.pixels(list, image_, PixelRect{0, 0, list.width, list.height}, targets.sceneFbo);
  ++drawing.stats.layerBuilds;
  identity_ = std::make_shared<const LayerIdentity>();
  version_ = restorableFrom_ = 0;
  updates_.clear();
}

// A frame over the retained layer: its image, with the dirty rectangles
// redrawn from the snapshot on. With a history that knows the image (see
// ImageHistory), only what differs from the layer image is put back: the
// rectangles the image's last frame wrote, and those the layer's updates
// since then changed. Returns the rectangles drawn.
std::vector<PixelRect> RetainedLayer::drawOver(const ViewDrawing& drawing, Readback& readback, const DrawList& list,
                                               const std::vector<ViewItems>& perView, const std::vector<bool>& fresh,
                                               media::Image& image, const ImageHistory::State* history) {
  const std::vector<PixelRect> rects = dirtyRects(drawing.caches, list, perView, fresh);
  RenderStats& stats = drawing.stats;
  stats.retainedPixels += static_cast<long long>(list.width) * list.height;
  for (const bool f : fresh) stats.freshViews += f ? 1 : 0;
  // A fresh view is read back whole below: its pixels in the layer are
  // not restored first (a follow camera's view, 5 MB at 1080p a frame).
  auto restore = [&](const PixelRect& r) {
    restoredParts_.assign(1, r);
    outsideFreshViews(list, fresh, restoredParts_, splitParts_);
    for (const PixelRect& part : restoredParts_) copyPixels(image_, image, part);
  };
  if (history != nullptr && history->layer == identity_ && history->version >= restorableFrom_) {
    for (const PixelRect& r : history->written) restore(r);
    for (const auto& [version, changed] : updates_)
      if (version > history->version)
        for (const PixelRect& r : changed) restore(r);
  } else if (std::find(fresh.begin(), fresh.end(), true) != fresh.end()) {
    restore(PixelRect{0, 0, list.width, list.height});
  } else {
    image.rgba = image_.rgba;  // same size: copies into the existing storage
  }
  std::vector<PixelRect> under = edgeRects_;
  redrawRects(drawing, readback, RedrawJob{list, perView, fresh}, rects, Items::All, image, &under);
  long long area = 0;
  for (const PixelRect& r : rects) area += static_cast<long long>(r.x1 - r.x0) * (r.y1 - r.y0);
  stats.redrawnPixels += area;
  return rects;
}

// The layer brought up to date in place (see layerChanges): its
// rectangles redrawn from the snapshot with the static items alone, as
// buildLayer draws them whole. A checkpoint of a growing line then costs
// about a frame over the layer instead of a frame drawn whole.
// A fresh view is not drawn: its pixels in the layer become stale.
void RetainedLayer::update(const ViewDrawing& drawing, Readback& readback, const DrawList& list,
                           const std::vector<ViewItems>& perView, const std::vector<PixelRect>& rects,
                           const std::vector<bool>& fresh) {
  redrawRects(drawing, readback, RedrawJob{list, perView, fresh}, rects, Items::StaticOnly, image_, nullptr);
  ++drawing.stats.layerUpdates;
  updates_.emplace_back(++version_, rects);
  if (updates_.size() > kUpdatesKept) {
    restorableFrom_ = updates_.front().first;  // an image at this version needs only the updates kept
    updates_.pop_front();
  }
}

ItemBounds itemBounds(GpuCaches& caches, const DrawList& list) {
  ItemBounds b;
  b.mesh = [&caches](const MeshItem& m, const View& v, const glm::mat4& clipFromWorld, std::vector<PixelRect>& out) {
    meshBounds(caches, v, clipFromWorld, Drawable{m.mesh, m.worldFromModel, &m.material, false}, out);
  };
  b.label = [&caches, &list](const LabelItem& l, const View* v, const glm::mat4& clipFromWorld) {
    return labelBounds(l, list, v, clipFromWorld, caches);
  };
  return b;
}

}  // namespace rollspin::render
