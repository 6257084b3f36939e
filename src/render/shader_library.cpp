#include "render/shader_library.hpp"

#include <fstream>
#include <sstream>
#include <string_view>
#include <utility>

#include "core/error.hpp"

namespace rollspin::render {

// Generated at build time from shaders/*.glsl (see embed_shaders.cmake).
std::string_view embeddedShader(std::string_view name);

std::string ShaderLibrary::source(const std::string& name) const {
  if (!overrideDir_.empty()) {
    // Named as in shaders/ ("mesh.frag" is mesh.frag.glsl), so that
    // --shader-dir shaders reads the working copy.
    const auto file = overrideDir_ / (name + ".glsl");
    std::ifstream in(file, std::ios::binary);
    if (!in) throw badInput({"--shader-dir " + overrideDir_.string()}, "cannot read shader '{}'", file.string());
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
  }
  const std::string_view text = embeddedShader(name);
  if (text.empty()) throw runtimeError({}, "shader '{}' is not embedded in this build", name);
  return std::string(text);
}

}  // namespace rollspin::render
