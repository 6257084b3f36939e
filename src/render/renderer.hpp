// Renderer — draws a DrawList with OpenGL 4.5 core: the opaque meshes that
// stay (and moving arrows) into a multisampled framebuffer object (default
// 4×), resolved into one of a single sample where everything else is drawn
// antialiased by its own coverage (ray-cast spheres, lines as capsules:
// coverage = clamp(½ + (edge distance)/(pixel size), 0, 1)); then reads the
// pixels back and, on the CPU, puts each view's backdrop behind them (out =
// c + (1 − a)·backdrop) and flips the bottom-up GL rows exactly once into a
// top-down Image. One key light with a shadow map per view, gamma-correct
// (sRGB) output. GPU copies of meshes, textures and glyph atlases are cached across
// frames, keyed by the shared data they came from. Retained layers: while
// the views and the static (not `dynamic`) items stay the same from frame to
// frame, their image is kept and a frame redraws only the rectangles its
// dynamic items touch, with the same bytes as a frame drawn whole.
#pragma once

#include <memory>
#include <vector>

#include "media/image_view.hpp"
#include "render/draw_list.hpp"
#include "render/gl_context.hpp"
#include "render/shader_library.hpp"

namespace rollspin::render {

// What the renderer did so far (tests, benchmarks, --verbose).
struct RenderStats {
  long long wholeFrames = 0;     // drawn whole (a still, a camera move, a span's first frame)
  long long layerBuilds = 0;     // retained layers built
  long long layerUpdates = 0;    // retained layers brought up to date in place (only static lines or labels changed)
  long long freshViews = 0;      // views drawn whole in frames over a layer (their camera moved, another's held)
  long long retainedFrames = 0;  // drawn over a retained layer
  long long redrawnPixels = 0;   // in those frames' rectangles, summed
  long long retainedPixels = 0;  // those frames' pixels, summed
  // Inside those rectangles a mesh or a line draws only its parts whose
  // screen bounds reach one (see drawMesh): what was offered and drawn.
  long long meshIndicesInRects = 0, meshIndicesDrawn = 0;
  long long lineSegmentsInRects = 0, lineSegmentsDrawn = 0;
  // Views drawn whole with multisampling: their pixels, and those drawn in
  // samples (the tiles near a mesh's edges, see view_pass.cpp's sampleTiles).
  long long wholeViewPixels = 0, sampledPixels = 0;
  // Translucent ray-cast spheres over a layer (the Bloch sphere's glass):
  // captured once, then replayed in each frame's rectangles (see glass_capture.hpp).
  long long sphereCaptures = 0, sphereReplays = 0;
};

// What a renderer last wrote into one image that nothing else writes (a
// video's pool of frames, a benchmark's one image). With it, a frame over
// the retained layer puts back only the rectangles where the image differs
// from the layer, instead of copying the whole layer image into it (8 MiB
// at 1080p). Anything else that writes the image's pixels must reset() it;
// a default one knows nothing (the whole layer image is copied).
class ImageHistory {
 public:
  ImageHistory();
  ~ImageHistory();
  ImageHistory(ImageHistory&&) noexcept;
  ImageHistory& operator=(ImageHistory&&) noexcept;
  void reset();

 private:
  friend class Renderer;
  friend class RetainedLayer;  // reads and writes what the image holds
  struct State;
  std::unique_ptr<State> state_;
};

class Renderer {
 public:
  // The context must stay current on this thread for the renderer's life.
  Renderer(GlContext& context, const ShaderLibrary& shaders);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Transparent lists come back with straight (not premultiplied) alpha;
  // opaque ones with alpha 255 everywhere.
  [[nodiscard]] media::Image render(const DrawList& list);
  // Same, into `image`, reusing its storage (frame after frame of a video).
  void render(const DrawList& list, media::Image& image);
  // Same, told what this renderer last wrote into `image` (see ImageHistory),
  // which it brings up to date.
  void render(const DrawList& list, media::Image& image, ImageHistory& history);
  // Same, then reads back the depth buffer of what was drawn: window depth in
  // [0, 1] (1 = nothing), top row first, width × height. Only meshes and
  // arrows write depth (lines and translucent items do not), so this is what
  // a depth-tested line is tested against. For vector figures.
  void renderWithDepth(const DrawList& list, media::Image& image, std::vector<float>& depth);
  // On by default; off draws every frame whole (the same bytes, slower).
  void setRetainLayers(bool on);
  [[nodiscard]] const RenderStats& stats() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace rollspin::render
