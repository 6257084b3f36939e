#include "render/programs.hpp"

#include <fmt/format.h>

namespace rollspin::render {

Programs::Programs(const ShaderLibrary& lib)
    : shadow(lib, "shadow.vert", "shadow.frag"),
      shadowSphere(lib, "impostor.vert", "shadow_sphere.frag"),
      line(lib, "line.vert", "line.frag", "line.geom"),
      text(lib, "text.vert", "text.frag"),
      depth(lib, "mesh.vert", "depth.frag", {}, "#define LIT 0\n"),
      sphereReplay(lib, "sphere_replay.vert", "sphere_replay.frag"),
      library_(lib) {}

Program& Programs::mesh(int pattern, bool shadowed, bool lit, bool specular, int impostor, bool vertexLit, bool capture,
                        bool coneCut) {
  const int key = (coneCut ? 512 : 0) + (capture ? 256 : 0) + (vertexLit ? 128 : 0) + impostor * 32 + pattern * 8 +
                  (shadowed ? 4 : 0) + (lit ? 2 : 0) + (specular ? 1 : 0);
  auto it = meshVariants_.find(key);
  if (it == meshVariants_.end()) {
    const std::string defines = fmt::format(
        "#define PATTERN {}\n#define SHADOWED {}\n#define LIT {}\n#define SPECULAR {}\n#define IMPOSTOR {}\n"
        "#define VERTEX_LIT {}\n#define CAPTURE {}\n#define CONE_CUT {}\n",
        pattern, shadowed ? 1 : 0, lit ? 1 : 0, specular ? 1 : 0, impostor, vertexLit ? 1 : 0, capture ? 1 : 0,
        coneCut ? 1 : 0);
    it = meshVariants_
             .emplace(key, Program(library_, impostor != 0 ? "impostor.vert" : "mesh.vert", "mesh.frag", {}, defines))
             .first;
  }
  return it->second;
}

Program& Programs::resolve(int samples) {
  if (resolver_ && resolverSamples_ != samples) resolver_.reset();
  if (!resolver_) {
    resolver_.emplace(library_, "fullscreen.vert", "resolve.frag", "", fmt::format("#define SAMPLES {}\n", samples));
    resolverSamples_ = samples;
  }
  return *resolver_;
}

}  // namespace rollspin::render
