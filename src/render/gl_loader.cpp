// Loads libOSMesa at run time and fills the GL function table (gl.hpp).
#include <dlfcn.h>

#include <cstdlib>
#include <mutex>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "render/gl.hpp"
#include "render/osmesa_api.hpp"

namespace rollspin::render::osmesa_api {
decltype(&OSMesaCreateContextAttribs) createContextAttribs = nullptr;
decltype(&OSMesaMakeCurrent) makeCurrent = nullptr;
decltype(&OSMesaDestroyContext) destroyContext = nullptr;
decltype(&OSMesaGetProcAddress) getProcAddress = nullptr;
}  // namespace rollspin::render::osmesa_api

#define ROLLSPIN_GL_DEFINE(name) ::rollspin::render::gl_api::name##_type name = nullptr;
ROLLSPIN_GL_FUNCTIONS(ROLLSPIN_GL_DEFINE)
#undef ROLLSPIN_GL_DEFINE

namespace rollspin::render {

namespace {

void* openLibrary(std::string& tried) {
  // ROLLSPIN_OSMESA_LIBRARY names the one library to use (another Mesa
  // build, or a test's missing one); else Debian's soname, then the dev link.
  std::vector<std::string> names;
  if (const char* custom = std::getenv("ROLLSPIN_OSMESA_LIBRARY"); custom != nullptr && *custom != '\0') {
    names.emplace_back(custom);
  } else {
    names.emplace_back("libOSMesa.so.8");
    names.emplace_back("libOSMesa.so");
  }
  for (const auto& name : names) {
    if (void* handle = dlopen(name.c_str(), RTLD_NOW | RTLD_LOCAL)) return handle;
    const char* why = dlerror();
    tried += (tried.empty() ? "" : "; ") + std::string(why != nullptr ? why : name);
  }
  return nullptr;
}

template <typename Fn>
void resolve(void* handle, Fn& target, const char* name) {
  target = reinterpret_cast<Fn>(dlsym(handle, name));
  if (target == nullptr) throw runtimeError({}, "libOSMesa has no {}: install Debian's libosmesa6", name);
}

void loadOnce() {
  std::string tried;
  void* handle = openLibrary(tried);
  if (handle == nullptr) {
    throw runtimeError({}, "cannot load the OSMesa library needed to draw ({}); install Debian's libosmesa6", tried);
  }
  resolve(handle, osmesa_api::createContextAttribs, "OSMesaCreateContextAttribs");
  resolve(handle, osmesa_api::makeCurrent, "OSMesaMakeCurrent");
  resolve(handle, osmesa_api::destroyContext, "OSMesaDestroyContext");
  resolve(handle, osmesa_api::getProcAddress, "OSMesaGetProcAddress");
#define ROLLSPIN_GL_LOAD(name)                                                                     \
  name = reinterpret_cast<gl_api::name##_type>(osmesa_api::getProcAddress(#name));                 \
  if (name == nullptr) throw runtimeError({}, "libOSMesa does not provide {}: OpenGL 4.5 needed", #name);
  ROLLSPIN_GL_FUNCTIONS(ROLLSPIN_GL_LOAD)
#undef ROLLSPIN_GL_LOAD
}

}  // namespace

void loadOsMesa() {
  // A failed load is retried by the next caller and throws again.
  static std::mutex mutex;
  static bool loaded = false;
  const std::lock_guard lock(mutex);
  if (loaded) return;
  loadOnce();
  loaded = true;
}

}  // namespace rollspin::render
