// Renderer::Impl: the renderer's state, gathered in one place, and the
// passes over a frame, one file each:
//   renderer.cpp        the frame: shadow maps, the layer plan, eviction
//   mesh_pass.cpp       the lit meshes (opaque, re-shade, translucent)
//   sphere_pass.cpp     ray-cast spheres
//   glass_capture.cpp   a translucent sphere captured once, replayed
//   shadow_pass.cpp     shadow maps          line_pass.cpp   polylines
//   text_pass.cpp       labels and frames    view_pass.cpp   a view's steps
//   readback.cpp        pixels and depth back to the CPU
//   retained_layers.cpp the retained layer: build, update, frames over it
// The GL objects (gl_objects), programs (programs), GPU caches (gpu_caches)
// and framebuffers (frame_targets) are classes of their own. Every draw
// takes a DrawScope (draw_scope.hpp). Renderer-internal.
#pragma once

#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "media/image_view.hpp"
#include "render/coverage_edges.hpp"
#include "render/draw_scope.hpp"
#include "render/font_atlas.hpp"
#include "render/frame_targets.hpp"
#include "render/gl_context.hpp"
#include "render/glass_capture.hpp"
#include "render/gpu_caches.hpp"
#include "render/layer_plan.hpp"
#include "render/programs.hpp"
#include "render/renderer.hpp"
#include "render/shadow_pass.hpp"

namespace rollspin::render {

// An image's pixels: the layer image `layer` at `version`, except inside
// `written` (a frame's rectangles). A layer's identity is an object of its
// own, which a history keeps alive: it never matches another layer, of this
// renderer or another.
struct ImageHistory::State {
  std::shared_ptr<const LayerIdentity> layer;  // null: unknown
  std::uint64_t version = 0;
  std::vector<PixelRect> written;
  const std::uint8_t* pixels = nullptr;  // the buffer it describes
};

struct Renderer::Impl {
  Impl(const GlContext& context, const ShaderLibrary& lib) : context(context), programs(lib) {}

  void render(const DrawList& list, media::Image& image, ImageHistory::State* history = nullptr);

  // ---- mesh_pass.cpp
  std::vector<Drawable> drawablesOf(const DrawList& list, int view, std::vector<Material>& arrowMaterials);
  void drawMesh(const Drawable& d, const DrawScope& scope, bool shadowOn, Cull cull, bool clipToShadowBox = false);
  void drawReshades(const ViewItems& viewItems, const DrawScope& scope);
  bool inSamplesPass(const Drawable& d) const { return !d.dynamic || (targets.opaqueFbo != 0 && !d.sphere); }
  void drawOpaque(const ViewItems& viewItems, const DrawScope& scope, Items which, Pass pass);
  void drawOpaqueAtCentres(const ViewItems& viewItems, const DrawScope& scope, Items which);
  // ---- sphere_pass.cpp
  void drawImpostor(const Drawable& d, const DrawScope& scope, Program& mesh, const PixelRect& rect, int pattern,
                    bool shadowed);
  void drawImpostorParts(Program& program, const View& v, const std::vector<PixelRect>& rects) const;
  // ---- glass_capture.cpp
  void replaySphere(const Drawable& d, const DrawScope& scope, const PixelRect& rect, int pattern,
                    const glm::mat4& worldFromClip, const glm::vec4& viewport);
  // ---- line_pass.cpp
  void drawPolyline(const PolylineItem& p, const DrawScope& scope);
  // ---- text_pass.cpp
  void drawQuads(std::span<const GlyphQuad> quads, glm::vec2 viewportSize, const glm::vec4& color, GLuint atlas,
                 bool solid);
  GpuFont* labelQuads(const LabelItem& label, glm::vec2 viewportSize, const glm::mat4* clipFromWorld,
                      std::vector<GlyphQuad>& quads);
  void drawLabelAs(const LabelItem& label, Items which, glm::vec2 viewportSize, const glm::mat4* clipFromWorld,
                   const DrawScope& scope);
  void drawImageLabels(const DrawList& list, Items which, const PixelRect& clip);
  PixelRect labelBounds(const LabelItem& l, const DrawList& list, const View* v, const glm::mat4& clipFromWorld);
  // ---- view_pass.cpp
  DrawScope beginView(const DrawList& list, const View& v, const ViewItems& viewItems, const PixelRect* clip,
                      GLuint fbo = 0);
  std::vector<PixelRect> sampleTiles(const DrawList& list, const View& v, const ViewItems& viewItems, Items which);
  std::vector<PixelRect> drawViewOpaque(const DrawList& list, const View& v, const ViewItems& viewItems, bool clear,
                                        std::vector<PixelRect>* under);
  void drawViewAfterOpaque(const DrawList& list, int view, const ViewItems& viewItems, std::vector<PixelRect> sampled,
                           const DrawScope& scope);
  void drawAfterResolve(const ViewItems& viewItems, const DrawScope& scope);
  void drawRest(const DrawList& list, int index, const ViewItems& viewItems, Items which, const DrawScope& scope);
  void drawWhole(const DrawList& list, const std::vector<ViewItems>& perView);
  void meshBounds(const View& v, const glm::mat4& clipFromWorld, const Drawable& d, std::vector<PixelRect>& out);
  // ---- readback.cpp
  void readBack(const DrawList& list, media::Image& image, const PixelRect& r);
  void readDepth(std::vector<float>& depth) const;
  void findLayerEdges(const DrawList& list);
  // ---- retained_layers.cpp
  void buildLayer(const DrawList& list, const std::vector<ViewItems>& perView);
  std::vector<PixelRect> drawOverLayer(const DrawList& list, const std::vector<ViewItems>& perView,
                                       const std::vector<bool>& fresh, media::Image& image,
                                       const ImageHistory::State* history);
  void updateLayer(const DrawList& list, const std::vector<ViewItems>& perView, const std::vector<PixelRect>& rects,
                   const std::vector<bool>& fresh);
  ItemBounds itemBounds(const DrawList& list);
  // A frame's lists, and its views drawn whole inside a frame over the layer.
  struct RedrawJob {
    const DrawList& list;
    const std::vector<ViewItems>& perView;
    const std::vector<bool>& fresh;
  };
  std::vector<PixelRect> dirtyRects(const DrawList& list, const std::vector<ViewItems>& perView,
                                    const std::vector<bool>& fresh);
  void forEachIsland(const RedrawJob& job, const std::vector<PixelRect>& rects, GLuint fbo,
                     std::vector<PixelRect>* under,
                     const std::function<void(std::size_t, const PixelRect&, const DrawScope&)>& island,
                     const std::function<void(std::size_t)>& whole = {});
  void redrawSamples(const RedrawJob& job, std::vector<PixelRect>* under);
  void redrawRects(const RedrawJob& job, const std::vector<PixelRect>& rects, Items which, media::Image& image,
                   std::vector<PixelRect>* under);

  const GlContext& context;  // current on this thread; named in GL errors
  bool retainLayers = true;
  Programs programs;
  VertexStreams streams;
  GpuCaches caches;
  FrameTargets targets;
  ShadowMaps shadowMaps;
  SphereCaptures captures;

  // The retained layer (see retained_layers.cpp): its keys, its finished
  // image of the static items, and that image's identity: a new one per
  // build, a new version per update in place, with the rectangles each
  // recent update changed (what an image drawn over an older version must
  // put back besides its own rectangles).
  struct Layer {
    LayerMemory memory;
    media::Image image;
    std::vector<PixelRect> edgeRects;  // tiles where its opaque meshes cover pixels in part
    std::shared_ptr<const LayerIdentity> identity;
    std::uint64_t version = 0, restorableFrom = 0;
    std::deque<std::pair<std::uint64_t, std::vector<PixelRect>>> updates;
    static constexpr std::size_t kUpdatesKept = 64;
  } layer;

  RenderStats stats;

  // Scratch storage that the passes reuse from draw to draw and frame to
  // frame (no allocation per draw); nothing in it outlives a call.
  struct Scratch {
    std::vector<PixelRect> parts, underParts;  // drawImpostor's
    std::vector<glm::vec3> replayCorners;      // replaySphere's
    RunsOfParts keptParts;                     // drawMesh's and drawPolyline's
    std::vector<GLsizei> runCounts;
    std::vector<const void*> runOffsets;
    std::vector<GLint> lineFirsts;
    std::vector<glm::vec3> paddedPoints;  // a polyline's points with its ends repeated
    std::vector<std::uint32_t> readRows;  // readBack's rows as read, bottom-up
    std::vector<std::pair<glm::vec3, glm::vec3>> backdropEnds;  // readBack's, per view
    std::vector<int> rowCuts;                                   // readBack's, per row
    std::vector<PixelRect> restoredParts, splitParts;           // drawOverLayer's
  } scratch;
};

}  // namespace rollspin::render
