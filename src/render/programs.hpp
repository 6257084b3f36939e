// The renderer's shader programs: the fixed ones, compiled once; the mesh
// program's variants (mesh.frag's defines), compiled on first use; the
// resolve program, for the sample count of the framebuffer it resolves.
// Renderer-internal.
#pragma once

#include <map>
#include <optional>

#include "render/gl_objects.hpp"
#include "render/shader_library.hpp"

namespace rollspin::render {

class Programs {
 public:
  explicit Programs(const ShaderLibrary& lib);

  // `impostor`: 0 the mesh's triangles, 1 a ray-cast sphere, 2 the same
  // under what is drawn (see SpherePass::draw); see mesh.frag.
  // `vertexLit`: lit per vertex with the highlight (an arrow's own meshes).
  // `capture`: a translucent sphere's capture (see glass_capture.hpp).
  // `coneCut`: the material's porthole (Material::cutCone) is cut out.
  Program& mesh(int pattern, bool shadowed, bool lit, bool specular, int impostor = 0, bool vertexLit = false,
                bool capture = false, bool coneCut = false);
  // resolve.frag for `samples` (made again when that changes).
  Program& resolve(int samples);

  Program shadow, shadowSphere, line, text, depth, sphereReplay;

 private:
  ShaderLibrary library_;  // a copy: mesh variants compile lazily
  std::map<int, Program> meshVariants_;
  std::optional<Program> resolver_;
  int resolverSamples_ = 0;
};

}  // namespace rollspin::render
