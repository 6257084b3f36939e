// The OSMesa backend: Mesa's off-screen library, always software (llvmpipe).
// libOSMesa is opened with dlopen when a job draws (never linked), so the
// binary runs without it. Mesa removed OSMesa in 25.1; the EGL backend
// (egl_context.cpp) covers those systems.
// gl.hpp first: it declares GL's prototypes before osmesa.h pulls in GL/gl.h.
#include "render/gl.hpp"

#include <GL/osmesa.h>

#include <array>
#include <mutex>
#include <string>

#include <dlfcn.h>

#include "core/error.hpp"
#include "render/gl_backend.hpp"

namespace rollspin::render {

namespace {

// What to try; the factory adds the other backends.
constexpr std::string_view kAdvice = "install Debian's libosmesa6 (scripts/install-deps.sh)";

// OSMesa's own entry points, resolved with dlsym.
struct OsMesaApi {
  decltype(&OSMesaCreateContextAttribs) createContextAttribs = nullptr;
  decltype(&OSMesaMakeCurrent) makeCurrent = nullptr;
  decltype(&OSMesaDestroyContext) destroyContext = nullptr;
  decltype(&OSMesaGetProcAddress) getProcAddress = nullptr;
};

// Loads libOSMesa once; returns null and sets `why` when it cannot (a failed
// load is retried by the next caller). ROLLSPIN_OSMESA_LIBRARY names another
// library file (a test's missing or broken one).
const OsMesaApi* loadOsMesa(std::string& why) {
  static std::mutex mutex;
  static OsMesaApi api;
  static bool loaded = false;
  const std::lock_guard lock(mutex);
  if (loaded) return &api;
  void* handle = openGlLibrary("ROLLSPIN_OSMESA_LIBRARY", {"libOSMesa.so.8", "libOSMesa.so"}, why);
  if (handle == nullptr) {
    why = "cannot load the OSMesa library needed to draw (" + why + ")";
    return nullptr;
  }
  auto resolve = [&](auto& target, const char* name) {
    target = reinterpret_cast<std::remove_reference_t<decltype(target)>>(dlsym(handle, name));
    if (target == nullptr && why.empty()) why = std::string("libOSMesa has no ") + name;
  };
  why.clear();
  resolve(api.createContextAttribs, "OSMesaCreateContextAttribs");
  resolve(api.makeCurrent, "OSMesaMakeCurrent");
  resolve(api.destroyContext, "OSMesaDestroyContext");
  resolve(api.getProcAddress, "OSMesaGetProcAddress");
  if (!why.empty()) return nullptr;
  loaded = true;
  return &api;
}

class OsMesaContext final : public GlContext {
 public:
  explicit OsMesaContext(const OsMesaApi& api) : api_(api) {
    const std::array<int, 11> attribs{OSMESA_FORMAT,
                                      OSMESA_RGBA,
                                      OSMESA_DEPTH_BITS,
                                      0,
                                      OSMESA_PROFILE,
                                      OSMESA_CORE_PROFILE,
                                      OSMESA_CONTEXT_MAJOR_VERSION,
                                      4,
                                      OSMESA_CONTEXT_MINOR_VERSION,
                                      5,
                                      0};
    context_ = api_.createContextAttribs(attribs.data(), nullptr);
    if (context_ == nullptr) {
      throw runtimeError({},
                         "OSMesa could not create an OpenGL 4.5 core context (OSMesaCreateContextAttribs "
                         "failed: is libosmesa6 from Mesa >= 20 installed? try scripts/install-deps.sh)");
    }
    // All drawing goes to the renderer's FBOs; OSMesa still wants a buffer
    // to make the context current, so give it a tiny one.
    if (!api_.makeCurrent(context_, placeholder_.data(), GL_UNSIGNED_BYTE, 1, 1)) {
      api_.destroyContext(context_);
      throw runtimeError({}, "OSMesa could not make its OpenGL context current (OSMesaMakeCurrent failed)");
    }
    try {
      loadGlFunctions(api_.getProcAddress, "libOSMesa");
    } catch (...) {
      api_.destroyContext(context_);
      throw;
    }
    info_.backend = "osmesa";
    readGlStrings(info_);
  }
  ~OsMesaContext() override { api_.destroyContext(context_); }
  OsMesaContext(const OsMesaContext&) = delete;
  OsMesaContext& operator=(const OsMesaContext&) = delete;

 private:
  const OsMesaApi& api_;
  OSMesaContext context_ = nullptr;
  std::array<unsigned char, 16> placeholder_{};
};

BackendProbe probe() {
  std::string why;
  if (loadOsMesa(why) == nullptr) return {BackendProbe::Reach::None, why};
  return {BackendProbe::Reach::Software, "libOSMesa loads (software: llvmpipe)"};
}

std::unique_ptr<GlContext> create(const std::optional<DeviceChoice>& /*device*/) {
  std::string why;
  const OsMesaApi* api = loadOsMesa(why);
  if (api == nullptr) throw runtimeError({}, "{}; {}", why, kAdvice);
  return std::make_unique<OsMesaContext>(*api);
}

}  // namespace

extern const GlBackend kOsMesaBackend{
    "osmesa", "Mesa's off-screen library: software (llvmpipe) only, no GPU; gone from Mesa >= 25.1",
    false,    kAdvice,
    &probe,   &create};

}  // namespace rollspin::render
