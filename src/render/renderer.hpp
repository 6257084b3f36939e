// Renderer — draws a DrawList with OpenGL 4.5 core into a multisampled
// framebuffer object (default 4×), resolves it, waits (glFinish), reads the
// pixels back and flips the bottom-up GL rows exactly once into a top-down
// Image. One key light with a shadow map per view, gamma-correct (sRGB)
// output. GPU copies of meshes, textures and glyph atlases are cached across
// frames, keyed by the shared data they came from.
#pragma once

#include <memory>
#include <vector>

#include "media/image_view.hpp"
#include "render/draw_list.hpp"
#include "render/gl_context.hpp"
#include "render/shader_library.hpp"

namespace rollspin::render {

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
  // Same, then reads back the depth buffer of what was drawn: window depth in
  // [0, 1] (1 = nothing), top row first, width × height. Only meshes and
  // arrows write depth (lines and translucent items do not), so this is what
  // a depth-tested line is tested against. For vector figures.
  void renderWithDepth(const DrawList& list, media::Image& image, std::vector<float>& depth);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace rollspin::render
