// GlContext — an OpenGL 4.5 core context made current on this thread, and the
// one factory that makes it: createContext() picks a backend from the table
// in gl_backends.cpp (render.backend / ROLLSPIN_GL: "auto" or a backend's
// name). The renderer draws into its own framebuffer objects, so a context
// needs no window and no default framebuffer of any particular size.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.hpp"

namespace rollspin::render {

// What a context runs on, for --verbose, `rollspin info` and tests.
struct ContextInfo {
  std::string backend;             // the table's name: "egl", …
  std::string platform;            // how the backend reached GL: "device", "surfaceless", "" (no choice)
  std::string device;              // the GPU or device used ("0: /dev/dri/renderD128 (hardware)"); "" = none
  std::string vendor;              // GL_VENDOR
  std::string renderer;            // GL_RENDERER
  std::string version;             // GL_VERSION
  bool software = false;           // GL_RENDERER is a CPU rasteriser (llvmpipe, softpipe, …)
  std::vector<std::string> notes;  // backends auto passed over and why; a requested device that renders in software
};

struct ContextRequest;

class GlContext {
 public:
  virtual ~GlContext() = default;
  [[nodiscard]] const ContextInfo& info() const { return info_; }
  // "egl (surfaceless): 4.5 (Core Profile) Mesa 22.3.6 on llvmpipe (…)".
  [[nodiscard]] std::string describe() const;

 protected:
  ContextInfo info_;

 private:
  friend std::unique_ptr<GlContext> createContext(const ContextRequest& request);  // adds auto's notes
};

// Which backend and device to use. A value left empty falls back to the
// environment (ROLLSPIN_GL, ROLLSPIN_EGL_DEVICE), then to "auto" / the
// backend's own choice: a scene key wins over the variable.
struct ContextRequest {
  std::optional<std::string> backend;  // "auto" or a name from backendNames()
  SourceLoc backendWhere;              // where it was given (scene key, flag), for messages
  std::optional<std::string> device;   // a device index ("1") or DRM path ("/dev/dri/renderD128")
  SourceLoc deviceWhere;
};

// Creates the context and makes it current; fills the GL function table.
// "auto": a backend that reaches a hardware device if any; else the first in
// the table that loads and makes a context (software). Throws Error: BadInput
// (exit 2) for an unknown backend name or a malformed device, naming where it
// came from and the choices; Runtime (exit 1) when the backend cannot be had,
// with the library's reason and what to try. With --verbose, prints
// describeContext() to stderr.
[[nodiscard]] std::unique_ptr<GlContext> createContext(const ContextRequest& request = {});

// "auto" and then every backend in the table, in auto's order of preference
// among software backends.
[[nodiscard]] std::vector<std::string> backendNames();
// Whether a device may be chosen for `name` ("auto" or a backend that takes
// one); false for unknown names.
[[nodiscard]] bool backendTakesDevice(std::string_view name);

// One line per backend: its name, whether it loads here, and what it found
// (the EGL devices, the library's reason when it does not load). Loads the
// libraries but makes no context: for `rollspin info`.
[[nodiscard]] std::vector<std::string> probeBackends();

// "backend   egl (surfaceless)\nGL_VENDOR …\n…": the lines --verbose and
// `rollspin info` print.
[[nodiscard]] std::string describeContext(const ContextInfo& info);

}  // namespace rollspin::render
