#include "render/shader_library.hpp"

#include <fstream>
#include <sstream>
#include <string_view>
#include <utility>

#include "core/error.hpp"

namespace rollspin::render {

// Generated at build time from shaders/*.glsl (see embed_shaders.cmake).
std::string_view embeddedShader(std::string_view name);

std::string ShaderLibrary::rawSource(const std::string& name) const {
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

// A line `#include "NAME"` is replaced by the source of NAME (NAME.glsl), so
// a function several shaders share lives in one file. GLSL has no include of
// its own; a cycle or a depth over 8 is an error.
std::string ShaderLibrary::source(const std::string& name, int depth) const {
  if (depth > 8) throw runtimeError({}, "shader '{}': #include nested more than 8 deep (a cycle?)", name);
  std::istringstream in(rawSource(name));
  std::string out, line;
  constexpr std::string_view directive = "#include \"";
  while (std::getline(in, line)) {
    if (line.rfind(directive, 0) == 0 && line.size() > directive.size() &&
        line.find('"', directive.size()) != std::string::npos) {
      const std::size_t end = line.find('"', directive.size());
      out += source(line.substr(directive.size(), end - directive.size()), depth + 1);
    } else {
      out += line + "\n";
    }
  }
  return out;
}

}  // namespace rollspin::render
