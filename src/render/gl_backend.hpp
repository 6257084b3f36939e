// One GL context backend as the table in gl_backends.cpp lists it: a name, an
// availability probe and a constructor. Private to render/: each backend's
// own file defines one GlBackend, and only the table refers to it by name.
#pragma once

#include <initializer_list>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "core/error.hpp"
#include "render/gl_context.hpp"

namespace rollspin::render {

// A device the user asked for (render.device or ROLLSPIN_EGL_DEVICE), still
// as text: the backend that takes devices parses it.
struct DeviceChoice {
  std::string text;
  SourceLoc where;
};

// What a probe found without making a context.
struct BackendProbe {
  enum class Reach { None, Software, Hardware };
  Reach reach = Reach::None;
  std::string detail;  // None: why (the library's reason); else what it found
};

struct GlBackend {
  std::string_view name;     // the value of render.backend / ROLLSPIN_GL
  std::string_view summary;  // one line for `rollspin info`
  bool takesDevice = false;  // render.device applies to it
  std::string_view advice;   // what to try when it cannot be had
  // Loads the library (once) and looks, making no context; never throws.
  BackendProbe (*probe)() = nullptr;
  // Makes the context current and fills the GL function table (gl.hpp);
  // throws Error (Runtime) naming the failing call, BadInput for a
  // malformed device.
  std::unique_ptr<GlContext> (*create)(const std::optional<DeviceChoice>& device) = nullptr;
};

// dlopen()s the first library that loads: the one named by the environment
// variable `overrideVariable` when it is set (a test's missing library, a
// custom build), else `names` in order. Never closes it (drivers keep
// threads and atexit handlers). Returns null and sets `why` (dlerror() of each
// attempt) when none loads.
[[nodiscard]] void* openGlLibrary(const char* overrideVariable, std::initializer_list<const char*> names,
                                  std::string& why);

// The GL_RENDERER strings of CPU rasterisers (Mesa's llvmpipe and softpipe,
// SwiftShader): a context on one of these does its work on the CPU.
[[nodiscard]] bool isSoftwareRenderer(std::string_view glRenderer);

// Fills info.vendor/renderer/version/software from the current context.
void readGlStrings(ContextInfo& info);

}  // namespace rollspin::render
