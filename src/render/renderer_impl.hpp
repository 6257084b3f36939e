// Renderer::Impl: the renderer's state, gathered in one place, and the
// frame that lends it to the steps (renderer.cpp: the shadow maps, the
// layer plan, eviction). The steps are functions and objects of their own
// that take what they read and write as arguments:
//   view_pass (view_pass.hpp)  a view's steps, drawing with a ViewDrawing
//                             (the programs, streams, caches, captures,
//                             framebuffers, mesh and line passes, stats)
//   RetainedLayer (retained_layers.hpp) the layer it owns (its image, keys
//                             and reused vectors): build, update, frames
//                             over it, with a ViewDrawing and the readback
// Each pass object holds only the vectors it reuses from draw to draw (no
// allocation per draw):
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
#include "render/retained_layers.hpp"
#include "render/shadow_pass.hpp"
#include "render/sphere_pass.hpp"
#include "render/text_pass.hpp"
#include "render/view_pass.hpp"

namespace rollspin::render {

struct Renderer::Impl {
  Impl(const GlContext& context, const ShaderLibrary& lib) : context(context), programs(lib) {}

  void render(const DrawList& list, media::Image& image, ImageHistory::State* history = nullptr);
  // Off: every frame drawn whole, and the layer's memory forgotten.
  void setRetainLayers(bool on);

  // What a frame's steps draw with (view_pass.hpp), lent for the frame.
  ViewDrawing drawing() { return {programs, streams, caches, captures, targets, meshes, lines, stats}; }

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

  RetainedLayer layer;  // the static items kept from frame to frame (retained_layers.hpp)

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
