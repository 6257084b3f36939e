// Shader sources by file name ("mesh.vert"). The GLSL files in shaders/ are
// embedded into the binary at build time (embed_shaders.cmake), so rollspin
// runs from any directory; a non-empty override directory (--shader-dir)
// reads them from disk instead (DIR/mesh.vert.glsl), for shader development.
// A line `#include "srgb"` pulls in shaders/srgb.glsl.
#pragma once

#include <filesystem>
#include <string>

namespace rollspin::render {

class ShaderLibrary {
 public:
  explicit ShaderLibrary(std::filesystem::path overrideDir = {}) : overrideDir_(std::move(overrideDir)) {}
  // The source with its `#include "NAME"` lines expanded. Throws Error:
  // BadInput for a missing file in the override directory, Runtime for a name
  // that was never embedded.
  [[nodiscard]] std::string source(const std::string& name, int depth = 0) const;

 private:
  [[nodiscard]] std::string rawSource(const std::string& name) const;
  std::filesystem::path overrideDir_;
};

}  // namespace rollspin::render
