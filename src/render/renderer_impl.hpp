// Renderer::Impl: the renderer's state, gathered in one place, and the
// steps of a frame that use all of it:
//   renderer.cpp        the frame: shadow maps, the layer plan, eviction
//   view_pass.cpp       a view's steps
//   retained_layers.cpp the retained layer: build, update, frames over it
// The passes they call are objects or functions of their own, and take
// what they read and write as arguments; each pass object holds only the
// vectors it reuses from draw to draw (no allocation per draw):
//   shadowPass (shadow_pass)  the view, its casters, the map, the caches,
//                             the programs and streams
//   MeshPass (mesh_pass)      the drawables, the scope, and MeshDrawing (the
//                             programs, caches, streams, captures, stats,
//                             framebuffers); it holds a SpherePass and the
//                             MeshRuns of a mesh inside a retained frame's
//                             rectangles
//   SpherePass (sphere_pass, its replay in glass_capture): the drawable,
//                             its scope and program, and SphereDrawing (the
//                             programs, streams, captures, stats, the
//                             framebuffer's size)
//   LinePass (line_pass)      the polyline, its scope, the line program,
//                             the streams, the framebuffer's height, stats
//   Readback (readback)       the list, the image, the rectangle and the
//                             scene framebuffer; readDepth and
//                             partlyCoveredTiles likewise
//   text_pass                 the label, its scope, and TextDrawing (the
//                             text program, streams, font caches); the
//                             scene framebuffer for image-level labels
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
#include "render/line_pass.hpp"
#include "render/mesh_pass.hpp"
#include "render/programs.hpp"
#include "render/readback.hpp"
#include "render/renderer.hpp"
#include "render/shadow_pass.hpp"
#include "render/sphere_pass.hpp"
#include "render/text_pass.hpp"

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
  // Off: every frame drawn whole, and the layer's memory forgotten.
  void setRetainLayers(bool on);

  // What the mesh pass (mesh_pass.hpp) draws with.
  MeshDrawing meshDrawing() { return {programs, caches, streams, captures, stats, targets}; }
  // What the text pass (text_pass.hpp) draws with.
  TextDrawing textDrawing() { return {programs.text, streams, caches}; }
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
  MeshPass meshes;
  LinePass lines;
  Readback readback;

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
    // What a frame over it restores from it, and the parts outside the
    // fresh views: reused from frame to frame (drawOverLayer, redrawRects).
    std::vector<PixelRect> restoredParts, splitParts;
  } layer;

  RenderStats stats;

  // Retained layers off for the guard's lifetime (a list drawn whole); the
  // previous setting back when it ends, also when the drawing throws.
  class RetainLayersOff {
   public:
    explicit RetainLayersOff(Impl& impl) : impl_(impl), previous_(impl.retainLayers) { impl_.setRetainLayers(false); }
    ~RetainLayersOff() { impl_.setRetainLayers(previous_); }
    RetainLayersOff(const RetainLayersOff&) = delete;
    RetainLayersOff& operator=(const RetainLayersOff&) = delete;

   private:
    Impl& impl_;
    bool previous_;
  };
};

}  // namespace rollspin::render
