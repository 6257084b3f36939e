#include "export/gltf_export.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "core/error.hpp"
#include "core/stage_log.hpp"
#include "draw/ball_view.hpp"
#include "draw/draw_style.hpp"
#include "export/gltf_builder.hpp"
#include "export/grid_thinning.hpp"
#include "motion/frame_sampling.hpp"
#include "motion/surface_stretches.hpp"
#include "render/mesh_builders.hpp"
#include "render/procedural_textures.hpp"

namespace rollspin::gltf {

using geometry::Vec3;
using spin::Su2;

namespace {

// The twin view's spin arrow radius; its field arrow is 0.8 of it.
constexpr float kArrowRadius = 0.028f;
constexpr int kArrowSegments = 32;
// How far the exported surface may depart from the ball view's mesh, in
// each direction of its grid. Where the ball rolls (within
// kNearPathOfRadius R of the contact path) a share of the ball's radius:
// the ball sinks into a chord by at most twice this (1 % of R, a pixel or
// less). Farther off, where nothing touches it, a share of the mesh's
// diagonal: about a pixel where the whole surface fills a 1080p frame.
constexpr double kSurfaceToleranceOfRadius = 0.005;
constexpr double kNearPathOfRadius = 3.0;
constexpr double kSurfaceToleranceOfDiagonal = 1.0 / 2000.0;
// The path tube's rings: kept where its centre line bends more than this
// share of the tube's radius off the chord between kept rings.
constexpr double kTubeToleranceOfItsRadius = 0.1;

void appendTransformed(render::MeshData& out, const render::MeshData& in, const glm::mat4& m) {
  const auto base = static_cast<std::uint32_t>(out.vertices.size());
  const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(m)));
  for (render::Vertex v : in.vertices) {
    v.position = glm::vec3(m * glm::vec4(v.position, 1.0f));
    v.normal = glm::normalize(normalMatrix * v.normal);
    out.vertices.push_back(v);
  }
  for (const std::uint32_t i : in.indices) out.indices.push_back(base + i);
}

// An arrow from the origin to `tip` as the renderer draws an ArrowItem.
render::MeshData arrowMesh(const glm::vec3& tip, float radius) {
  const render::ArrowParts parts = render::arrowParts(glm::vec3(0.0f), tip, radius);
  render::MeshData arrow;
  appendTransformed(arrow, *render::unitCylinder(kArrowSegments), parts.shaft);
  appendTransformed(arrow, *render::unitCone(kArrowSegments), parts.head);
  return arrow;
}

// The surface as the ball view shows it: its cut-away dropped (glTF cannot
// cut; a triangle stays if any corner is on the kept side), the checker's
// cells as texture coordinates of a 2 × 2-cell image (checkerTexture). A
// world-space checker (a steep chart) falls back to the chart's own cells.
render::MeshData surfaceForExport(const render::MeshData& mesh, const render::Material& material) {
  render::MeshData out;
  const glm::vec2 scale = material.pattern == render::Pattern::Checker ? material.patternScale : glm::vec2(1.0f);
  for (render::Vertex v : mesh.vertices) {
    v.uv *= 0.5f * scale;
    out.vertices.push_back(v);
  }
  auto kept = [&](std::uint32_t i) {
    return glm::dot(material.cutPlane, glm::vec4(mesh.vertices[i].position, 1.0f)) >= 0.0f;
  };
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
    if (kept(mesh.indices[t]) || kept(mesh.indices[t + 1]) || kept(mesh.indices[t + 2]))
      out.indices.insert(out.indices.end(), {mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]});
  for (const render::Vertex& v : out.vertices)
    if (!std::isfinite(v.position.x) || !std::isfinite(v.position.y) || !std::isfinite(v.position.z)) return {};
  return out;
}

// The contact path as a tube of radius r lying on the surface: centred at
// P(s) + r n(s), round the tangent (the mesher's patch: a along s, b round).
std::shared_ptr<render::MeshData> pathTube(const model::RollingModel& model, double r) {
  const geometry::ContactPath& path = *model.path;
  const int along = static_cast<int>(std::clamp(480.0 * std::max(1.0, path.turns()), 480.0, 20000.0));
  return render::parametricPatch(
      [&](float a, float b, glm::vec3& p, glm::vec3& n) {
        const geometry::DarbouxSample f = path.at(path.length() * double(a));
        const double beta = 2.0 * std::numbers::pi * double(b);
        const Vec3 radial = std::cos(beta) * f.tangentNormal + std::sin(beta) * f.normal;
        p = draw::toGlm(f.point + r * f.normal + r * radial);
        n = draw::toGlm(radial);
      },
      along, 12);
}

// The rotation taking +z to the unit vector b by the shorter arc.
Su2 fromZTo(const Vec3& b) {
  const double w = 1.0 + b.z();
  if (w < 1e-12) return {0.0, 1.0, 0.0, 0.0};  // b = −z: half a turn about x
  const Su2 q{w, -b.y(), b.x(), 0.0};          // (1 + z·b, z × b), normalised below
  const double n = q.norm();
  return {q.w / n, q.x / n, q.y / n, q.z / n};
}

// Float32 quaternions (x, y, z, w) on one hemisphere key to key, so that
// any interpolation (a per-component one too) turns the short way.
std::vector<glm::vec4> continuousQuaternions(const std::vector<Su2>& q) {
  std::vector<glm::vec4> out;
  glm::vec4 previous(0.0f, 0.0f, 0.0f, 1.0f);
  for (const Su2& k : q) {
    const double n = k.norm();
    glm::vec4 v(float(k.x / n), float(k.y / n), float(k.z / n), float(k.w / n));
    if (glm::dot(v, previous) < 0.0f) v = -v;
    out.push_back(v);
    previous = v;
  }
  return out;
}

// Float32 quaternions (x, y, z, w) in canonical form, w ≥ 0, as glTF readers
// normalise them; `sign` gets the spinor's sign back: sign × key = q.
std::vector<glm::vec4> canonicalQuaternions(const std::vector<Su2>& q, std::vector<float>& sign) {
  std::vector<glm::vec4> out;
  for (const Su2& k : q) {
    const double n = k.norm();
    const float flip = k.w < 0.0 ? -1.0f : 1.0f;
    sign.push_back(flip);
    out.push_back(flip * glm::vec4(float(k.x / n), float(k.y / n), float(k.z / n), float(k.w / n)));
  }
  return out;
}

int addSampler(tinygltf::Animation& animation, int input, int output) {
  tinygltf::AnimationSampler sampler;
  sampler.input = input;
  sampler.output = output;
  sampler.interpolation = "LINEAR";
  animation.samplers.push_back(sampler);
  return int(animation.samplers.size() - 1);
}

void addChannel(tinygltf::Animation& animation, int sampler, int node, const std::string& path) {
  tinygltf::AnimationChannel channel;
  channel.sampler = sampler;
  channel.target_node = node;
  channel.target_path = path;
  animation.channels.push_back(channel);
}

struct Nodes {
  int root = -1, ball = -1, bloch = -1, spin = -1, field = -1;
  std::vector<int> surfaces, paths;  // one of each per surface the clip shows (a surface: −1 for none)
};

// glTF has no visibility: each surface's nodes (its surface and path) are
// scaled 1 while the clip shows that surface and 0 otherwise, STEP keys at
// `starts` (the clip's seconds where each surface is first shown).
void addVisibility(GltfBuilder& b, tinygltf::Animation& roll, const Nodes& nodes, const std::vector<float>& starts) {
  const int times = b.addScalars(starts);
  for (std::size_t k = 0; k < starts.size(); ++k) {
    std::vector<glm::vec3> scales;
    for (std::size_t i = 0; i < starts.size(); ++i) scales.emplace_back(i == k ? 1.0f : 0.0f);
    const int sampler = addSampler(roll, times, b.addVec3(scales, 0));
    roll.samplers.back().interpolation = "STEP";
    for (const int node : {nodes.surfaces[k], nodes.paths[k]})
      if (node >= 0) addChannel(roll, sampler, node, "scale");
  }
}

// Animation "roll" and the ball's extras.rollspin.
void addRoll(GltfBuilder& b, const RollKeys& keys, const Nodes& nodes, const ExportRequest& r,
             const std::vector<float>& surfaceStarts) {
  tinygltf::Animation roll;
  roll.name = "roll";
  const int times = b.addScalars(keys.seconds);
  std::vector<glm::vec3> centres;
  for (const Vec3& c : keys.centre) centres.push_back(draw::toGlm(c));
  std::vector<float> signs;
  const int ballRotation = b.addVec4(canonicalQuaternions(keys.rotation, signs));
  std::vector<Su2> fieldTurns;
  for (const Vec3& f : keys.field) fieldTurns.push_back(fromZTo(f));
  const int fieldRotation = b.addVec4(continuousQuaternions(fieldTurns));
  const int translation = addSampler(roll, times, b.addVec3(centres, 0));
  const int rotation = addSampler(roll, times, ballRotation);
  addChannel(roll, translation, nodes.ball, "translation");
  addChannel(roll, rotation, nodes.ball, "rotation");
  addChannel(roll, rotation, nodes.spin, "rotation");
  addChannel(roll, addSampler(roll, times, fieldRotation), nodes.field, "rotation");
  if (surfaceStarts.size() > 1) addVisibility(b, roll, nodes, surfaceStarts);
  b.model().animations.push_back(roll);

  std::vector<float> arcLength(keys.arcLength.begin(), keys.arcLength.end());
  tinygltf::Value::Object extras;
  extras["arc_length"] = tinygltf::Value(b.addScalars(arcLength));
  extras["spinor_sign"] = tinygltf::Value(b.addScalars(signs));
  extras["version"] = tinygltf::Value(r.version);
  if (r.metadata) extras["scene"] = tinygltf::Value(r.sceneText);
  tinygltf::Value::Object outer;
  outer["rollspin"] = tinygltf::Value(extras);
  b.model().nodes[std::size_t(nodes.ball)].extras = tinygltf::Value(outer);
}

void setPose(tinygltf::Node& node, const Vec3& translation, const Su2& q) {
  node.translation = {translation.x(), translation.y(), translation.z()};
  node.rotation = {q.x, q.y, q.z, q.w};
}

}  // namespace

namespace {

// The clip's seconds where each surface stretch is first shown, 0 for the
// first: just after the whole frame before its first segment's first frame
// (the renders' cut), where its motion starts and the ball jumps to it
// (roll_keys.cpp).
std::vector<float> surfaceStartSeconds(const scene::SceneSpec& spec, const model::RollingModel& model,
                                       const std::vector<motion::SurfaceStretch>& stretches) {
  std::vector<float> starts{0.0f};
  if (stretches.size() < 2) return starts;
  const motion::FrameClock clock = motion::clipClock(spec, model);
  long long frame = 0;
  for (std::size_t k = 1; k < stretches.size(); ++k) {
    while (frame + 1 < clock.frameCount() && clock.place(frame).segment < stretches[k].firstSegment) ++frame;
    starts.push_back(secondsJustAfter(double(frame - 1), clock.fps().value()));
  }
  return starts;
}

struct Built {
  GltfBuilder builder;
  RollKeys keys;
  Vec3 blochCentre = Vec3::Zero();
  double blochRadius = 1.0;
};

// Each vertex's tolerance for thinning the surface's grid (see
// kSurfaceToleranceOfRadius): fine within kNearPathOfRadius R of a point
// of the contact path (sampled every R/4, in cells of that size), coarse
// farther off, never finer than near it.
std::vector<double> surfaceTolerances(const render::MeshData& mesh, const model::RollingModel& model) {
  const double R = model.ballRadius, near = kNearPathOfRadius * R, fine = kSurfaceToleranceOfRadius * R;
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (const render::Vertex& v : mesh.vertices) {
    lo = glm::min(lo, v.position);
    hi = glm::max(hi, v.position);
  }
  const double coarse = std::max(fine, kSurfaceToleranceOfDiagonal * double(glm::length(hi - lo)));
  const geometry::ContactPath& path = *model.path;
  // A point's cell, or none where it is not finite (a chart the path
  // leaves: the mesh is refused after this) or beyond any cell index.
  const auto cellOf = [&](const Vec3& p) -> std::optional<std::array<long long, 3>> {
    std::array<long long, 3> cell{};
    for (int k = 0; k < 3; ++k) {
      const double at = std::floor(p[k] / near);
      if (!std::isfinite(at) || std::abs(at) > 1e15) return std::nullopt;
      cell[std::size_t(k)] = std::llround(at);
    }
    return cell;
  };
  std::map<std::array<long long, 3>, std::vector<Vec3>> cells;
  const int samples = int(std::clamp(std::ceil(path.length() / (0.25 * R)), 2.0, 200000.0));
  for (int k = 0; k <= samples; ++k) {
    const Vec3 p = path.point(path.length() * double(k) / double(samples));
    if (const auto cell = cellOf(p)) cells[*cell].push_back(p);
  }
  std::vector<double> tolerances;
  tolerances.reserve(mesh.vertices.size());
  for (const render::Vertex& v : mesh.vertices) {
    const Vec3 p(v.position.x, v.position.y, v.position.z);
    const auto c = cellOf(p);
    bool isNear = !c;  // (fine where unknown)
    for (long long dx = -1; dx <= 1 && !isNear; ++dx)
      for (long long dy = -1; dy <= 1 && !isNear; ++dy)
        for (long long dz = -1; dz <= 1 && !isNear; ++dz) {
          const auto found = cells.find({(*c)[0] + dx, (*c)[1] + dy, (*c)[2] + dz});
          if (found == cells.end()) continue;
          for (const Vec3& q : found->second)
            if ((q - p).norm() <= near) {
              isNear = true;
              break;
            }
        }
    tolerances.push_back(isNear ? fine : coarse);
  }
  return tolerances;
}

// The surface node, or none where the scene has no surface. A surface the
// ball view could not mesh (no point of the path on its chart, or a chart
// that is not finite where the path runs) is bad input.
int addSurface(GltfBuilder& b, const draw::BallView& view, const scene::SceneSpec& spec,
               const model::RollingModel& model, const std::string& name) {
  if (!model.surface) return -1;
  const auto mesh = view.surfaceMesh();
  // The renders' grid is fine everywhere (4 vertices a checker cell); the
  // file keeps only the rows and columns its curvature needs.
  const render::MeshData shown =
      mesh ? surfaceForExport(thinGrid(*mesh, surfaceTolerances(*mesh, model)), view.surfaceMaterial())
           : render::MeshData{};
  if (shown.indices.empty())
    throw badInput(spec.where("surface.kind"),
                   "surface.kind: the {} surface cannot be meshed where the path runs "
                   "(no finite patch of it holds the path), so it cannot be exported",
                   spec.surface.kind.name());
  const render::Material& material = view.surfaceMaterial();
  const int texture = b.addTexture(*render::checkerTexture(material.color, material.color2), name + "-checker");
  return b.addNode(name, b.addMesh(name, shown, b.addMaterial(name, material, texture), true));
}

// The ball: the view's sphere at radius R about the node, with its texture
// and the view's ball material.
int addBall(GltfBuilder& b, const draw::BallView& view, double R) {
  render::MeshData ball;
  appendTransformed(ball, *view.ballMesh(), glm::scale(glm::mat4(1.0f), glm::vec3(float(R))));
  render::Material material;
  material.specular = 0.12f;  // BallView::add's ball material
  material.shininess = 24.0f;
  const int texture = b.addTexture(*view.ballTexture(), "ball");
  return b.addNode("ball", b.addMesh("ball", ball, b.addMaterial("ball", material, texture), true));
}

int addPath(GltfBuilder& b, const model::RollingModel& model, const std::string& name) {
  render::Material material;
  material.color = glm::vec3(draw::kPathLineColor);
  material.specular = 0.0f;
  const double radius = 0.03 * model.ballRadius;
  // Fewer rings where the path runs straight; every side of each ring stays.
  const render::MeshData tube = thinGrid(*pathTube(model, radius), kTubeToleranceOfItsRadius * radius, 0.0);
  return b.addNode(name, b.addMesh(name, tube, b.addMaterial(name, material), false));
}

// The Bloch sphere and its arrows, as the twin view draws them.
void addBloch(GltfBuilder& b, Nodes& nodes, const Vec3& markerBody) {
  const render::Material glass = draw::glassMaterial({0.62f, 0.76f, 0.95f}, 0.16f, 0.5f, 90.0f);
  nodes.bloch = b.addNode("bloch", b.addMesh("bloch", *render::uvSphere(64, 32), b.addMaterial("bloch", glass), false));
  render::Material arrow;  // the renderer's arrow material
  arrow.specular = render::kArrowSpecular;
  arrow.shininess = render::kArrowShininess;
  arrow.color = draw::kMarkerColor;
  nodes.spin = b.addNode(
      "spin", b.addMesh("spin", arrowMesh(draw::toGlm(markerBody), kArrowRadius), b.addMaterial("spin", arrow), false));
  arrow.color = draw::kFieldColor;
  nodes.field = b.addNode("field", b.addMesh("field", arrowMesh(glm::vec3(0, 0, 1), 0.8f * kArrowRadius),
                                             b.addMaterial("field", arrow), false));
  b.model().nodes[std::size_t(nodes.bloch)].children = {nodes.spin, nodes.field};
}

// The Bloch sphere beside everything the file shows (the surface as meshed,
// what the ball view frames), past its +x side, mid-height, large enough to
// read next to it.
void placeBloch(Built& out, const std::vector<std::unique_ptr<draw::BallView>>& views, double R) {
  Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
  auto grow = [&](const Vec3& p) {
    if (!p.allFinite()) return;
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  };
  for (const auto& view : views) {
    for (const Vec3& p : view->extent().points) grow(p);
    if (view->surfaceMesh())
      for (const render::Vertex& v : view->surfaceMesh()->vertices)
        grow(Vec3(v.position.x, v.position.y, v.position.z));
  }
  out.blochRadius = std::max(2.0 * R, 0.15 * (hi - lo).norm());
  out.blochCentre = Vec3(hi.x() + 1.5 * out.blochRadius, 0.5 * (lo.y() + hi.y()), 0.5 * (lo.z() + hi.z()));
}

Built build(const ExportRequest& r) {
  // The ball view meshes the surface only where a layout shows the ball.
  scene::SceneSpec spec = *r.spec;
  if (spec.render.layout == scene::RenderLayout::Twin) spec.render.layout = scene::RenderLayout::SideBySide;
  const model::RollingModel& model = *r.model;
  const double R = model.ballRadius;
  Vec3 markerBody = spec.ball.marker ? Vec3((*spec.ball.marker)[0], (*spec.ball.marker)[1], (*spec.ball.marker)[2])
                                     : model.path->at(0.0).normal;  // as SceneDrawer
  markerBody.normalize();
  // One ball view per surface the clip shows (a storyboard's surface
  // stretches, each meshed round its own path, as the renders do).
  const std::vector<motion::SurfaceStretch> stretches = motion::surfaceStretches(spec, model);
  std::vector<std::unique_ptr<draw::BallView>> views;
  if (stretches.empty())
    views.push_back(std::make_unique<draw::BallView>(spec, model, r.ballTexture, nullptr, markerBody,
                                                     render::uvSphere(8, 4), draw::FigureText{}));
  for (const motion::SurfaceStretch& st : stretches)
    views.push_back(std::make_unique<draw::BallView>(st.spec, st.model, r.ballTexture, nullptr, markerBody,
                                                     render::uvSphere(8, 4), draw::FigureText{}));
  Built out;
  GltfBuilder& b = out.builder;
  Nodes nodes;
  nodes.root = b.addNode("rollspin");
  const double h = std::sqrt(0.5);  // −90° about x: scene +z up → glTF +y up
  b.model().nodes[std::size_t(nodes.root)].rotation = {-h, 0.0, 0.0, h};
  for (std::size_t k = 0; k < views.size(); ++k) {
    const std::string suffix = k == 0 ? "" : "." + std::to_string(k);
    const scene::SceneSpec& partSpec = stretches.empty() ? spec : stretches[k].spec;
    const model::RollingModel& partModel = stretches.empty() ? model : stretches[k].model;
    nodes.surfaces.push_back(addSurface(b, *views[k], partSpec, partModel, "surface" + suffix));
    nodes.paths.push_back(addPath(b, partModel, "path" + suffix));
    // At rest (no animation played) the file shows the clip's first surface.
    for (const int node : {nodes.surfaces.back(), nodes.paths.back()})
      if (node >= 0 && k > 0) b.model().nodes[std::size_t(node)].scale = {0.0, 0.0, 0.0};
  }
  nodes.ball = addBall(b, *views.front(), R);
  addBloch(b, nodes, markerBody);
  out.keys = rollKeys(spec, model);
  setPose(b.model().nodes[std::size_t(nodes.ball)], out.keys.centre.front(), out.keys.rotation.front());
  setPose(b.model().nodes[std::size_t(nodes.spin)], Vec3::Zero(), out.keys.rotation.front());
  setPose(b.model().nodes[std::size_t(nodes.field)], Vec3::Zero(), fromZTo(out.keys.field.front()));
  placeBloch(out, views, R);
  tinygltf::Node& bloch = b.model().nodes[std::size_t(nodes.bloch)];
  bloch.translation = {out.blochCentre.x(), out.blochCentre.y(), out.blochCentre.z()};
  bloch.scale = {out.blochRadius, out.blochRadius, out.blochRadius};
  std::vector<int> children;
  for (std::size_t k = 0; k < views.size(); ++k) children.insert(children.end(), {nodes.surfaces[k], nodes.paths[k]});
  children.insert(children.end(), {nodes.ball, nodes.bloch});
  for (const int child : children)
    if (child >= 0) b.model().nodes[std::size_t(nodes.root)].children.push_back(child);
  if (r.animation) addRoll(b, out.keys, nodes, r, surfaceStartSeconds(spec, model, stretches));
  tinygltf::Scene scene;
  scene.name = spec.name;
  scene.nodes = {nodes.root};
  b.model().scenes.push_back(scene);
  b.model().defaultScene = 0;
  return out;
}

}  // namespace

GltfBuilder buildModel(const ExportRequest& request) { return std::move(build(request).builder); }

ExportedScene exportScene(const ExportRequest& request) {
  Built built = build(request);
  StageLog::instance().record("gltf-write");
  return {built.builder.glb(), std::move(built.keys), built.blochCentre, built.blochRadius};
}

std::vector<std::uint8_t> exportGlb(const ExportRequest& request) { return exportScene(request).glb; }

}  // namespace rollspin::gltf
