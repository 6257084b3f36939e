// GlContext — an OpenGL 4.5 core context made current on this thread, behind
// an interface so that an EGL (GPU) backend can be added without touching the
// renderer. The renderer draws into its own framebuffer objects, so a context
// needs no window and no default framebuffer of any particular size.
#pragma once

#include <memory>
#include <string>

namespace rollspin::render {

class GlContext {
 public:
  virtual ~GlContext() = default;
  // "OSMesa: 4.5 (Core Profile) Mesa 22.3.6 on llvmpipe (...)".
  [[nodiscard]] virtual std::string describe() const = 0;
};

// Creates an OSMesa (software, llvmpipe) core 4.5 context and makes it
// current. Throws Error (Runtime → exit 1) with a clear message on failure.
[[nodiscard]] std::unique_ptr<GlContext> createOsMesaContext();

}  // namespace rollspin::render
