// What the renderer's passes share: the items a view draws (Drawable,
// ViewItems), which of them a step takes (Items, Pass), and the state one
// draw depends on, passed to it as a value (DrawScope) rather than left in
// members by the caller. Renderer-internal.
#pragma once

#include <glm/glm.hpp>

#include <array>
#include <memory>
#include <vector>

#include "render/draw_list.hpp"
#include "render/gl_objects.hpp"
#include "render/screen_bounds.hpp"

namespace rollspin::render {

// Everything a view draws as a lit mesh: its MeshItems plus its arrows.
struct Drawable {
  std::shared_ptr<const MeshData> mesh;
  glm::mat4 worldFromModel;
  const Material* material;
  bool dynamic = false;  // see MeshItem::dynamic
  bool sphere = false;   // see MeshItem::sphere
  // An arrow's cylinder or cone (opaque, plain, culled, its facets a
  // pixel or two wide): lit per vertex, see mesh.vert's VERTEX_LIT.
  bool litPerVertex = false;
};

// A view's shadow map (a depth texture with hardware comparison).
struct ShadowMap {
  GlObject fbo, texture;
};

// How a view's receivers sample its shadow map.
struct ShadowSetup {
  glm::mat4 lightClipFromWorld{1.0f};
  float filterRadius = 0.0f;  // PCF radius in map uv
};

// What one view draws, gathered before anything is drawn so that the
// shadow maps can be rendered first (see Renderer::Impl::render).
struct ViewItems {
  std::vector<Material> arrowMaterials;  // the arrows' Drawables point here
  std::vector<Drawable> items;
  const ShadowMap* shadowMap = nullptr;  // null: no shadow
  ShadowSetup shadow;
};

// Which items a drawing step takes: a retained layer is drawn from the
// static ones; a frame (whole, or a rectangle over a layer) from all.
enum class Items { StaticOnly, DynamicOnly, All };
inline bool takes(Items which, bool dynamic) { return which == Items::All || (which == Items::DynamicOnly) == dynamic; }

// Where an opaque mesh is drawn: with the static ones, in their samples
// (Pass::Samples: every static mesh, and a moving one that is not a
// sphere, an arrow say, whose triangle edges the samples antialias), or
// after the resolve at one sample (Pass::Coverage: a moving sphere,
// ray-cast with its coverage; every moving mesh at msaa = 1).
enum class Pass { Samples, Coverage };

// The state a draw depends on. beginView makes one for the view and the
// framebuffer it binds; a step narrows a copy of it for its draws.
struct DrawScope {
  const View* view = nullptr;     // its camera, light and viewport
  glm::mat4 clipFromWorld{1.0f};  // the view's camera, multiplied once
  ShadowSetup shadow;             // the view's shadow map's, if any
  int samples = 1;                // a ray-cast sphere needs 1 (see impostorRect)
  bool depthOnly = false;         // colour writes are off (see drawOpaqueAtCentres)
  // Over a retained layer (and for a tile drawn in samples): the
  // rectangles an island redraws; a mesh, a line or a label draws only its
  // parts that reach one. Null: everywhere.
  const std::vector<PixelRect>* clips = nullptr;
  // Where an opaque ray-cast sphere's under pass (SpherePass::draw) can change
  // a pixel: in a view drawn whole, its tiles drawn in samples; over a
  // retained layer, the layer's edge tiles and the tiles of moving meshes
  // drawn in samples; and the rectangles of the spheres drawn before it in
  // the frame, which each adds. Null: everywhere.
  std::vector<PixelRect>* under = nullptr;
};

// A ray-cast sphere's pixels: one pixel of its coverage ramp lies outside
// the silhouette, one more for rounding; drawn in bands of 16 rows (see
// sphereBands; narrower bands fit closer, but each is a draw).
inline constexpr float kImpostorMarginPx = 2.0f;
inline constexpr int kImpostorBandRows = 16;

// The eight corners of the box [lo, hi], placed by `transform`.
std::array<glm::vec3, 8> boxCorners(const glm::vec3& lo, const glm::vec3& hi,
                                    const glm::mat4& transform = glm::mat4(1.0f));

// Image pixels (top-left origin) to the view's normalized device coordinates.
glm::vec4 ndcRectOf(const View& v, const PixelRect& rect);

// The uniforms of a mesh program for `d` in `scope` (each program ignores
// those it lacks). See mesh_pass.cpp.
void setMeshUniforms(Program& mesh, const Drawable& d, const DrawScope& scope, bool clipToShadowBox);

// The five clip planes of mesh.vert (a material's cut, the shadow box),
// enabled while it lives.
class ClipDistances {
 public:
  ClipDistances();
  ~ClipDistances();
  ClipDistances(const ClipDistances&) = delete;
  ClipDistances& operator=(const ClipDistances&) = delete;
};

}  // namespace rollspin::render
