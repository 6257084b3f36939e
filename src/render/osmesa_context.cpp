
#include <array>
#include <vector>

#include "core/error.hpp"
#include "core/stage_log.hpp"
#include "render/gl.hpp"
#include "render/osmesa_api.hpp"
#include "render/gl_context.hpp"

namespace rollspin::render {

namespace {

class OsMesaContext final : public GlContext {
 public:
  OsMesaContext() {
    StageLog::instance().record("gl-context");
    loadOsMesa();
    const std::array<int, 11> attribs{OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 0, OSMESA_PROFILE,
                                      OSMESA_CORE_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION, 4,
                                      OSMESA_CONTEXT_MINOR_VERSION, 5, 0};
    context_ = osmesa_api::createContextAttribs(attribs.data(), nullptr);
    if (context_ == nullptr) {
      throw runtimeError({}, "OSMesa could not create an OpenGL 4.5 core context (is libosmesa6 from Mesa >= 20 "
                             "installed? try scripts/install-deps.sh)");
    }
    // All drawing goes to the renderer's FBOs; OSMesa still wants a buffer
    // to make the context current, so give it a tiny one.
    if (!osmesa_api::makeCurrent(context_, placeholder_.data(), GL_UNSIGNED_BYTE, 1, 1)) {
      osmesa_api::destroyContext(context_);
      throw runtimeError({}, "OSMesa could not make its OpenGL context current");
    }
    const auto* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    description_ = fmt::format("OSMesa: {} on {}", version ? version : "?", renderer ? renderer : "?");
  }
  ~OsMesaContext() override { osmesa_api::destroyContext(context_); }
  OsMesaContext(const OsMesaContext&) = delete;
  OsMesaContext& operator=(const OsMesaContext&) = delete;

  [[nodiscard]] std::string describe() const override { return description_; }

 private:
  OSMesaContext context_ = nullptr;
  std::array<unsigned char, 16> placeholder_{};
  std::string description_;
};

}  // namespace

std::unique_ptr<GlContext> createOsMesaContext() { return std::make_unique<OsMesaContext>(); }

}  // namespace rollspin::render
