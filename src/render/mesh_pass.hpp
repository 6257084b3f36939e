// The mesh pass: the lit meshes of a view (its MeshItems and its arrows),
// the opaque ones in samples or at one sample, the receivers' re-shade in
// the shadow box, the translucent ones; a sphere drawn at one sample is
// handed to the ray cast (sphere_pass.hpp). Renderer-internal.
#pragma once

#include <vector>

#include "render/draw_scope.hpp"
#include "render/frame_targets.hpp"
#include "render/glass_capture.hpp"
#include "render/gpu_caches.hpp"
#include "render/programs.hpp"
#include "render/renderer.hpp"
#include "render/screen_bounds.hpp"
#include "render/sphere_pass.hpp"

namespace rollspin::render {

// The view's drawables: its meshes, and its arrows as a cylinder and a cone
// each (their materials kept in `arrowMaterials`); every mesh named stays
// cached in `caches`.
std::vector<Drawable> drawablesOf(const DrawList& list, int view, std::vector<Material>& arrowMaterials,
                                  GpuCaches& caches);

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

// What meshes are drawn with: the programs, the GPU caches (meshes,
// textures), the vertex streams, the translucent spheres' captures, the
// counters, and the frame's framebuffers (their size, samples, and whether
// opaque items are drawn in samples).
struct MeshDrawing {
  Programs& programs;
  GpuCaches& caches;
  const VertexStreams& streams;
  SphereCaptures& captures;
  RenderStats& stats;
  const FrameTargets& targets;
};

// Draws meshes; holds the sphere pass and the runs it reuses.
class MeshPass {
 public:
  // Whether `d` is drawn with the opaque items in samples (else at one
  // sample, after the resolve): a static item, or a moving one that is no
  // sphere where the frame has a samples framebuffer.
  [[nodiscard]] static bool inSamplesPass(const Drawable& d, const FrameTargets& targets) {
    return !d.dynamic || (targets.opaqueFbo != 0 && !d.sphere);
  }
  void draw(const Drawable& d, const DrawScope& scope, bool shadowOn, Cull cull, const MeshDrawing& with,
            bool clipToShadowBox = false);
  void drawReshades(const ViewItems& viewItems, const DrawScope& scope, const MeshDrawing& with);
  void drawOpaque(const ViewItems& viewItems, const DrawScope& scope, Items which, Pass pass, const MeshDrawing& with);
  void drawOpaqueAtCentres(const ViewItems& viewItems, const DrawScope& scope, Items which, const MeshDrawing& with);

 private:
  SpherePass spheres_;
  MeshRuns runs_;
};

}  // namespace rollspin::render
