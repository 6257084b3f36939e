// DrawList — everything one image shows, as plain data: meshes with model
// matrices and materials, arrows, polylines and text labels, grouped into
// views (rectangles of the image, each with its camera and light). The
// renderer draws it and knows nothing of rolling or spinors; jobs/ fills it
// (the way MuJoCo's mjv_updateScene fills an abstract scene). Colours are
// linear RGB in [0, 1]; the renderer encodes sRGB on output.
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace rollspin::render {

struct Vertex {
  glm::vec3 position{0.0f};
  glm::vec3 normal{0.0f, 0.0f, 1.0f};
  glm::vec2 uv{0.0f};
};

struct MeshData {
  std::vector<Vertex> vertices;
  std::vector<std::uint32_t> indices;  // triangles
};

// RGBA8 texture, top row first, sRGB-encoded colours (decoded on sampling).
struct TextureImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;
};

// SolidChecker: cubes of 1 / patternScale.x in world space, for a surface
// whose chart stretches its cells (a steep height field): where the surface
// meets the cubes, cells of about that size whatever the slope.
enum class Pattern { Plain, Checker, Texture, SolidChecker };
enum class Cull { Back, Front, None };

struct Material {
  glm::vec3 color{0.8f};
  glm::vec3 color2{0.6f};  // Checker: the second colour
  float opacity = 1.0f;    // < 1: drawn after opaque items, sorted far to near
  float specular = 0.25f;
  float shininess = 48.0f;
  Pattern pattern = Pattern::Plain;
  glm::vec2 patternScale{1.0f};                 // Checker: cells per unit of uv; SolidChecker: cells per world unit (x)
  std::shared_ptr<const TextureImage> texture;  // Pattern::Texture
  bool lit = true;
  bool castsShadow = true;
  // Shows the key light's shadow (the surfaces). Off for convex solids such
  // as balls and arrows, whose own n·l shading already darkens their far
  // side: the shadow filter is the most expensive part of a frame.
  bool receivesShadow = false;
  Cull cull = Cull::Back;  // Cull::None: lit on whichever side faces the camera
  // Keep only the part with dot(cutPlane, (p, 1)) >= 0 (world p): a
  // cut-away, e.g. the near half of a sphere the ball rolls inside.
  glm::vec4 cutPlane{0.0f, 0.0f, 0.0f, 1.0f};
  // A porthole towards a point a surface hides (w > 0): drop the part inside
  // the cone from the view's eye through the sphere (xyz, radius w) that
  // lies nearer the eye than its centre (draw/ marks its rim with a line).
  glm::vec4 cutCone{0.0f};
  bool operator==(const Material&) const = default;
};

// `dynamic` (on every item kind): the item may change from frame to frame
// (the ball, its trails, the live numbers). The renderer keeps everything
// else of a view in a retained layer while it stays the same, and redraws
// only the screen rectangles the dynamic items touch (see renderer.hpp).
// Meshes compare by pointer: a MeshData is immutable once shared.
struct MeshItem {
  std::shared_ptr<const MeshData> mesh;
  glm::mat4 worldFromModel{1.0f};
  Material material;
  int view = 0;
  // A small opaque unit sphere (a mark) that a vector figure draws as a flat
  // disc of its projected radius instead of as an image; GL ignores it.
  bool figureDisc = false;
  // The mesh is a unit sphere about the model origin and worldFromModel a
  // similarity (rotation, uniform scale, translation): in a framebuffer of
  // one sample, where no sample finds its edge, the renderer ray-casts it
  // per pixel with analytic edge coverage instead of drawing its triangles;
  // a shadow map takes its depth ray-cast per texel.
  bool sphere = false;
  // The backing plate of a text block (a screen-aligned quad): drawn as any
  // translucent mesh; a figure's layout (figureLayout) reports its rectangle.
  bool textPlate = false;
  bool dynamic = false;
  bool operator==(const MeshItem&) const = default;
};

// A solid arrow (cylinder + cone) from origin to tip.
struct ArrowItem {
  glm::vec3 origin{0.0f};
  glm::vec3 tip{0.0f, 0.0f, 1.0f};
  float shaftRadius = 0.02f;
  glm::vec3 color{0.8f, 0.1f, 0.1f};
  int view = 0;
  bool dynamic = false;
  bool operator==(const ArrowItem&) const = default;
};

// A polyline of constant width in pixels, each segment a screen-space capsule:
// round joins and round caps (line.geom, line.frag).
struct PolylineItem {
  std::vector<glm::vec3> points;
  glm::vec4 color{0.0f, 0.0f, 0.0f, 1.0f};
  float widthPx = 2.0f;
  bool depthTested = true;
  // The contact path or a trail, not a grid, axis or rim line: labels keep
  // off it (draw/ places them so; a figure's layout reports it).
  bool labelsKeepOff = false;
  int view = 0;
  bool dynamic = false;
  bool operator==(const PolylineItem&) const = default;
};

enum class Align { Left, Center, Right };

// Text in UTF-8. view < 0: `anchor.xy` is in image pixels (top-left origin).
// view >= 0 with worldAnchored: `anchor` is a world point projected by that
// view's camera; otherwise anchor.xy is in the view's pixels.
struct LabelItem {
  std::string text;
  glm::vec3 anchor{0.0f};
  bool worldAnchored = false;
  glm::vec2 offsetPx{0.0f};  // added after projection; +y is down
  float sizePx = 16.0f;
  glm::vec4 color{0.0f, 0.0f, 0.0f, 1.0f};
  Align align = Align::Left;
  bool bold = false;
  int view = -1;
  bool dynamic = false;
  // A dynamic label whose first bytes (whole words, "s = " of "s = 3.78")
  // are the same in every frame: drawn left-aligned, they keep their place
  // whatever follows, so a retained layer keeps them and a frame redraws
  // only the rest (see staticPartOf). 0: the whole label is dynamic.
  std::size_t staticPrefixBytes = 0;
  bool operator==(const LabelItem&) const = default;
};

struct Camera {
  glm::mat4 viewFromWorld{1.0f};
  glm::mat4 clipFromView{1.0f};
  glm::vec3 position{0.0f, 0.0f, 1.0f};
  bool operator==(const Camera&) const = default;
};

// One directional key light with an optional shadow map that covers the
// sphere (shadowCenter, shadowRadius) — the renderer narrows it across the
// light to the casters' bounds, and receivers outside it skip the filter —
// plus hemispheric ambient fill.
struct Light {
  glm::vec3 towardLight = glm::normalize(glm::vec3(0.4f, -0.3f, 1.0f));
  glm::vec3 color{1.0f};
  float ambient = 0.35f;
  bool shadow = true;
  glm::vec3 shadowCenter{0.0f};
  float shadowRadius = 10.0f;
  float shadowSoftness = 0.1f;  // PCF radius in world units: a soft key light
  bool operator==(const Light&) const = default;
};

struct View {
  int x = 0, y = 0, width = 0, height = 0;  // pixels, top-left origin
  Camera camera;
  Light light;
  bool background = true;                           // gradient; off for transparent output
  glm::vec3 backgroundTop{0.30f, 0.38f, 0.50f};     // linear RGB: a soft slate-blue sky
  glm::vec3 backgroundBottom{0.82f, 0.84f, 0.87f};  // that lightens towards the horizon
  bool frame = false;                               // thin border (an inset)
  bool operator==(const View&) const = default;
};

// A new item kind must also be known to the renderer's retained layers
// (renderer.cpp: StaticKey, dirtyRects, and drawn in drawRest by `takes`),
// or a change to it would not reach the frames drawn over a layer.
struct DrawList {
  int width = 1280;
  int height = 720;
  int msaaSamples = 4;       // 1 disables multisampling
  bool transparent = false;  // alpha 0 where nothing is drawn; PNG keeps alpha
  std::vector<View> views;
  std::vector<MeshItem> meshes;
  std::vector<ArrowItem> arrows;
  std::vector<PolylineItem> polylines;
  std::vector<LabelItem> labels;
  // Texts the layout meant to draw but found no room for (a heading, a
  // fact, a caption, the title, an axis label), each once, whole (a line
  // broken to fit as one): a figure names them (jobs/figure_job).
  std::vector<std::string> leftOut;
};

}  // namespace rollspin::render
