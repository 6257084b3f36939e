// The view pass: a view's steps over a frame, in order (retained_layers.hpp
// gives the order and why). The opaque meshes at one sample, then in
// samples in the tiles near their edges, resolved there (drawViewOpaque);
// then at one sample, each step antialiased by its own coverage: the
// re-shade and the moving spheres (drawAfterResolve), lines, translucent
// meshes and overlays (drawRest). Each step takes what it draws with as
// arguments: the GL state it binds is set by beginView, scope by scope.
// Renderer-internal.
#pragma once

#include <vector>

#include "render/draw_list.hpp"
#include "render/draw_scope.hpp"
#include "render/frame_targets.hpp"
#include "render/gpu_caches.hpp"
#include "render/line_pass.hpp"
#include "render/mesh_pass.hpp"
#include "render/programs.hpp"
#include "render/text_pass.hpp"

namespace rollspin::render {

// What a view's steps draw with, lent by the renderer for one frame: the
// programs, vertex streams and GPU caches, the sphere captures, the frame's
// framebuffers, the mesh and line passes (each with its own reused
// vectors), and the counters they add to.
struct ViewDrawing {
  Programs& programs;
  VertexStreams& streams;
  GpuCaches& caches;
  SphereCaptures& captures;
  FrameTargets& targets;
  MeshPass& meshes;
  LinePass& lines;
  RenderStats& stats;

  [[nodiscard]] MeshDrawing meshDrawing() const { return {programs, caches, streams, captures, stats, targets}; }
  [[nodiscard]] TextDrawing textDrawing() const { return {programs.text, streams, caches}; }
};

// Binds the scene (or `fbo`), the view's viewport and shadow map, scissored
// to `clip` (image pixels, top-left origin; the view's own rectangle if
// null); the scope of the draws that follow.
[[nodiscard]] DrawScope beginView(const FrameTargets& targets, const DrawList& list, const View& v,
                                  const ViewItems& viewItems, const PixelRect* clip, GLuint fbo = 0);

// The tiles of view v where the opaque meshes drawn in samples (`which` of
// them) can cover a pixel in part.
[[nodiscard]] std::vector<PixelRect> sampleTiles(GpuCaches& caches, const FrameTargets& targets, const DrawList& list,
                                                 const View& v, const ViewItems& viewItems, Items which);

// A mesh's screen bounds, as rectangles that together hold it (appended to `out`).
void meshBounds(GpuCaches& caches, const View& v, const glm::mat4& clipFromWorld, const Drawable& d,
                std::vector<PixelRect>& out);

// A view's opaque meshes drawn whole; returns the tiles drawn in samples.
std::vector<PixelRect> drawViewOpaque(const ViewDrawing& drawing, const DrawList& list, const View& v,
                                      const ViewItems& viewItems, bool clear, std::vector<PixelRect>* under);

// After drawViewOpaque: the steps at one sample (`sampled`: its tiles).
void drawViewAfterOpaque(const ViewDrawing& drawing, const DrawList& list, int view, const ViewItems& viewItems,
                         std::vector<PixelRect> sampled, const DrawScope& scope);

// What a frame draws at one sample after the resolve, before drawRest.
void drawAfterResolve(const ViewDrawing& drawing, const ViewItems& viewItems, const DrawScope& scope);

// Everything after the opaque meshes and the re-shade.
void drawRest(const ViewDrawing& drawing, const DrawList& list, int index, const ViewItems& viewItems, Items which,
              const DrawScope& scope);

// The whole frame, as the static items' layer and dynamic items would draw it.
void drawWhole(const ViewDrawing& drawing, const DrawList& list, const std::vector<ViewItems>& perView);

}  // namespace rollspin::render
