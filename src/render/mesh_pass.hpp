// The mesh pass's part over a retained layer: of a mesh's triangles, only
// the runs whose screen bounds reach the rectangles being redrawn, drawn in
// one call. Renderer-internal.
#pragma once

#include <vector>

#include "render/draw_scope.hpp"
#include "render/gpu_caches.hpp"
#include "render/renderer.hpp"
#include "render/screen_bounds.hpp"

namespace rollspin::render {

// Draws a mesh's runs of triangles inside a retained frame's rectangles;
// holds the runs it reuses from draw to draw (no allocation per draw).
class MeshRuns {
 public:
  // The bound mesh `g` (its VAO bound), its chunks placed by clipFromModel,
  // in the rectangles scope.clips (not null); counted in `stats`.
  void draw(const GpuMesh& g, const glm::mat4& clipFromModel, const DrawScope& scope, RenderStats& stats);

 private:
  RunsOfParts kept_;
  std::vector<GLsizei> counts_;
  std::vector<const void*> offsets_;
};

}  // namespace rollspin::render
