// The GL function table (gl.hpp) and what every backend shares to fill it:
// opening its library with dlopen, resolving GL through its GetProcAddress,
// reading the context's strings.
#include <dlfcn.h>

#include <cstdlib>
#include <mutex>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "render/gl.hpp"
#include "render/gl_backend.hpp"

// `name` expands to ::rollspin::render::gl_api::name (gl.hpp): the declarator
// is parenthesised so that clang does not read `T ::ns::name` as `T::ns::name`.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wparentheses"  // g++ calls the needed parentheses unnecessary
#define ROLLSPIN_GL_DEFINE(name) ::rollspin::render::gl_api::name##_type(name) = nullptr;
ROLLSPIN_GL_FUNCTIONS(ROLLSPIN_GL_DEFINE)
#undef ROLLSPIN_GL_DEFINE
#pragma GCC diagnostic pop

namespace rollspin::render {

void* openGlLibrary(const char* overrideVariable, std::initializer_list<const char*> names, std::string& why) {
  // The override names the one library to use (another build, or a test's
  // missing one): falling back to the system's would hide what it tests.
  std::vector<std::string> candidates;
  if (const char* custom = std::getenv(overrideVariable); custom != nullptr && *custom != '\0') {
    candidates.emplace_back(custom);
  } else {
    candidates.assign(names.begin(), names.end());
  }
  why.clear();
  for (const auto& name : candidates) {
    // RTLD_NODELETE: GL libraries stay mapped to the end of the process, so
    // LeakSanitizer can still name them (tests/lsan.supp) after a dlclose.
    if (void* handle = dlopen(name.c_str(), RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE)) return handle;
    const char* error = dlerror();
    why += (why.empty() ? "" : "; ") + std::string(error != nullptr ? error : name);
  }
  return nullptr;
}

namespace {
// Contexts are made on several threads in tests; the table is process-wide.
std::mutex tableMutex;
GlProcResolver tableResolver = nullptr;  // the one that filled the table last
}  // namespace

void loadGlFunctions(GlProcResolver resolve, std::string_view library) {
  const std::lock_guard lock(tableMutex);
  tableResolver = resolve;
#define ROLLSPIN_GL_LOAD(name) \
  name = reinterpret_cast<gl_api::name##_type>(resolve(#name)); \
  if (name == nullptr) throw runtimeError({}, "{} does not provide {}: OpenGL 4.5 needed", library, #name);
  ROLLSPIN_GL_FUNCTIONS(ROLLSPIN_GL_LOAD)
#undef ROLLSPIN_GL_LOAD
}

GlProc glProcAddress(const char* name) {
  const std::lock_guard lock(tableMutex);
  return tableResolver != nullptr ? tableResolver(name) : nullptr;
}

bool isSoftwareRenderer(std::string_view glRenderer) {
  for (std::string_view cpu : {"llvmpipe", "softpipe", "SwiftShader", "Software Rasterizer"})
    if (glRenderer.find(cpu) != std::string_view::npos) return true;
  return false;
}

void readGlStrings(ContextInfo& info) {
  auto text = [](GLenum name) {
    const auto* s = reinterpret_cast<const char*>(glGetString(name));
    return std::string(s != nullptr ? s : "?");
  };
  info.vendor = text(GL_VENDOR);
  info.renderer = text(GL_RENDERER);
  info.version = text(GL_VERSION);
  info.software = isSoftwareRenderer(info.renderer);
}

}  // namespace rollspin::render
