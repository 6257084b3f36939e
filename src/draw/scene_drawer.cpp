#include "draw/scene_drawer.hpp"

#include "core/stage_log.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/gtc/matrix_transform.hpp>

#include "draw/draw_facts.hpp"
#include "render/mesh_builders.hpp"
#include "render/procedural_textures.hpp"
#include "spin/field.hpp"

namespace rollspin::draw {

// The drawing reads the solving side's poses and facts.
using namespace rollspin::motion;

namespace {

using geometry::Vec3;
constexpr double kDeg = std::numbers::pi / 180.0;

glm::vec3 toGlm(const Vec3& v) { return {float(v.x()), float(v.y()), float(v.z())}; }

// worldFromBody as a glm matrix (the rotation of U).
glm::mat4 rotationOf(const spin::Su2& q) {
  const spin::Mat3 r = q.rotationMatrix();
  glm::mat4 m(1.0f);
  for (int c = 0; c < 3; ++c)
    for (int row = 0; row < 3; ++row) m[c][row] = float(r(row, c));
  return m;
}

// The palette: muted surfaces, saturated actors (linear RGB).
const glm::vec3 kMarkerColor{0.80f, 0.04f, 0.03f};
const glm::vec3 kFieldColor{0.03f, 0.22f, 0.78f};
const glm::vec4 kPathColor{0.10f, 0.16f, 0.32f, 0.55f};
const glm::vec4 kTravelledColor{0.95f, 0.33f, 0.02f, 1.0f};
const glm::vec4 kTextColor{0.04f, 0.05f, 0.07f, 1.0f};

// The text size, at most `preferred`, at which the longest line fits in
// `widthPx`: small images shrink their text rather than clip it. DejaVu Sans
// averages under 0.6 em per character (bold 0.66).
float sizeToFit(const std::vector<std::string>& lines, float widthPx, float preferred, bool bold) {
  std::size_t longest = 1;
  for (const auto& line : lines)
    longest = std::max<std::size_t>(longest, std::count_if(line.begin(), line.end(), [](char c) {
                                      return (static_cast<unsigned char>(c) & 0xC0) != 0x80;  // UTF-8 lead bytes
                                    }));
  return std::max(7.0f, std::min(preferred, widthPx / ((bold ? 0.66f : 0.6f) * float(longest))));
}

struct OrbitAngles {
  double azimuth = 0.0, elevation = 0.0;  // radians
};

bool isCircuit(const RollingModel& model) { return model.path->turns() > 0.0; }

OrbitAngles orbitAngles(const scene::SceneSpec& spec, const RollingModel& model);
Vec3 towardEye(const OrbitAngles& a) {
  return {std::cos(a.elevation) * std::cos(a.azimuth), std::cos(a.elevation) * std::sin(a.azimuth),
          std::sin(a.elevation)};
}

}  // namespace

SceneDrawer::SceneDrawer(const scene::SceneSpec& spec, const RollingModel& model,
                         std::shared_ptr<const render::TextureImage> ballTexture,
                         std::shared_ptr<const SceneFacts> facts)
    : spec_(spec), model_(model), ballTexture_(std::move(ballTexture)), facts_(std::move(facts)) {
  const double R = model.ballRadius;
  const double length = model.path->length();
  const geometry::DarbouxSample start = model.path->at(0.0);
  markerBody_ = spec.ball.marker ? Vec3((*spec.ball.marker)[0], (*spec.ball.marker)[1], (*spec.ball.marker)[2])
                                 : start.normal;
  markerBody_.normalize();

  const int samples = 1 + static_cast<int>(std::clamp(480.0 * std::max(1.0, model.path->turns()), 480.0, 20000.0));
  Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
  for (int i = 0; i < samples; ++i) {
    const double s = length * i / (samples - 1);
    const geometry::DarbouxSample f = model.path->at(s);
    pathS_.push_back(s);
    pathPoints_.push_back(f.point);
    const Vec3 c = f.centre(R);
    if (i % std::max(1, samples / 240) == 0) framePoints_.push_back(c);
    lo = lo.cwiseMin(c - Vec3::Constant(R));
    hi = hi.cwiseMax(c + Vec3::Constant(R));
  }
  // Cameras: [render]'s (with the defaults orbitAngles derives), then each
  // segment's keys laid over the previous segment's camera.
  const OrbitAngles base = orbitAngles(spec, model);
  Shot shot{base.azimuth, base.elevation, spec.render.fovDeg, std::nullopt, spec.render.distance, spec.render.follow};
  if (spec.render.target) shot.target = Vec3((*spec.render.target)[0], (*spec.render.target)[1], (*spec.render.target)[2]);
  titleBand_ = !spec.render.title.empty();
  for (const scene::SegmentSpec& seg : spec.segments) {
    const scene::CameraSpec& c = seg.camera;
    if (c.azimuthDeg) shot.azimuth = *c.azimuthDeg * kDeg;
    if (c.elevationDeg) shot.elevation = *c.elevationDeg * kDeg;
    if (c.fovDeg) shot.fovDeg = *c.fovDeg;
    if (c.distance) shot.distance = *c.distance;
    if (c.follow) shot.follow = *c.follow;
    if (c.follow && *c.follow) shot.target.reset();
    if (c.target) {
      shot.target = Vec3((*c.target)[0], (*c.target)[1], (*c.target)[2]);
      shot.follow = false;
    }
    shots_.push_back(shot);
    if (seg.title && !seg.title->empty()) titleBand_ = true;
  }
  if (shots_.empty()) shots_.push_back(shot);

  dotMesh_ = render::uvSphere(24, 12);  // small dots need few triangles
  const bool layoutShowsTwin = spec.render.layout != scene::RenderLayout::Ball;
  if (layoutShowsTwin) {
    StageLog::instance().record("twin-geometry");
    blochSphereMesh_ = render::uvSphere(64, 32);
    if (facts_ && facts_->phaseSplit) fieldConeMesh_ = coneMesh(facts_->phaseSplit->fieldLoop);
  }
  const bool layoutShowsBall = spec.render.layout != scene::RenderLayout::Twin;
  if (!layoutShowsBall) return;  // the twin needs none of the surface geometry
  StageLog::instance().record("surface-mesh");
  if (!ballTexture_) ballTexture_ = render::tennisBallTexture();

  // Small triangles are costly on llvmpipe (each shades whole 4×4 blocks):
  // 64 segments keep the silhouette within 0.2 px of a circle up to 1440p.
  sphereMesh_ = spec.render.height > 1440 ? render::uvSphere(96, 48) : render::uvSphere(64, 32);
  // Surfaces receive the ball's shadow but cast none: a surface shadowing
  // itself only adds acne, and where the ball's shadow would pass through a
  // surface to its far side, that side faces away from the light anyway.
  surfaceMaterial_.castsShadow = false;
  surfaceMaterial_.receivesShadow = true;
  surfaceMaterial_.specular = 0.0f;  // matte: cheaper, and no glare on the board
  surfaceMaterial_.shininess = 16.0f;
  surfaceMaterial_.pattern = render::Pattern::Checker;
  surfaceMaterial_.cull = render::Cull::None;

  if (const auto* plane = dynamic_cast<const geometry::Plane*>(model.surface.get())) {
    // A square board under the path; checker cells of size R so that the
    // distance rolled can be counted.
    const Vec3 n = plane->normal();
    const Vec3 mid = 0.5 * (lo + hi);
    const Vec3 centre = mid - n * n.dot(mid);
    const double half = 0.5 * (hi - lo).norm() + 3.0 * R;
    const Vec3 e1 = geometry::defaultTangentFor(n), e2 = n.cross(e1);
    surfaceMesh_ = render::parametricPatch(
        [&](float a, float b, glm::vec3& p, glm::vec3& nn) {
          p = toGlm(centre + (2.0 * a - 1.0) * half * e1 + (2.0 * b - 1.0) * half * e2);
          nn = toGlm(n);
        },
        1, 1);  // flat: two triangles (large ones let llvmpipe shade whole tiles)
    for (auto& v : surfaceMesh_->vertices) {
      const Vec3 p(v.position.x, v.position.y, v.position.z);
      v.uv = glm::vec2(float(p.dot(e1) / R), float(p.dot(e2) / R));  // cells of size R, a corner at the origin
    }
    surfaceMaterial_.color = {0.80f, 0.78f, 0.74f};
    surfaceMaterial_.color2 = {0.55f, 0.56f, 0.58f};
    surfaceMaterial_.patternScale = glm::vec2(1.0f);
  } else if (const auto* sphere = dynamic_cast<const geometry::Sphere*>(model.surface.get())) {
    const double r = sphere->radius();
    const double c0 = 0.0, c1 = std::numbers::pi;
    if (sphere->side() == geometry::Side::Inside) {
      // Cut away the cap that faces the camera, so the ball inside is seen
      // wherever it rolls; a rim line marks the cut.
      const Vec3 toEye = towardEye(orbitAngles(spec, model));
      const double offset = 0.25 * r;
      surfaceMaterial_.cutPlane = glm::vec4(-toGlm(toEye), float(offset));
      const Vec3 e1 = Vec3::UnitZ().cross(toEye).normalized(), e2 = toEye.cross(e1);
      const double rimRadius = std::sqrt(r * r - offset * offset);
      for (int k = 0; k <= 180; ++k) {
        const double phi = 2.0 * std::numbers::pi * k / 180;
        cutRim_.push_back(offset * toEye + rimRadius * (std::cos(phi) * e1 + std::sin(phi) * e2));
      }
    }
    surfaceMesh_ = render::parametricPatch(
        [&](float a, float b, glm::vec3& p, glm::vec3& nn) {
          const double phi = 2.0 * std::numbers::pi * a, th = c0 + (c1 - c0) * b;
          const Vec3 d(std::sin(th) * std::cos(phi), std::sin(th) * std::sin(phi), std::cos(th));
          p = toGlm(r * d);
          nn = toGlm(-d);  // the patch winds inward; lighting flips by facing anyway
        },
        128, std::max(8, int(64 * (c1 - c0) / std::numbers::pi)),
        glm::vec2(24.0f, float(12.0 * (c1 - c0) / std::numbers::pi)));
    surfaceMaterial_.color = {0.72f, 0.74f, 0.78f};
    surfaceMaterial_.color2 = {0.52f, 0.56f, 0.62f};
    for (int i = 0; i <= 8; ++i)
      for (int k = 0; k < 16; ++k) {
        const double th = c0 + (c1 - c0) * i / 8, phi = 2.0 * std::numbers::pi * k / 16;
        framePoints_.push_back(r * Vec3(std::sin(th) * std::cos(phi), std::sin(th) * std::sin(phi), std::cos(th)));
      }
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], -r);
      hi[k] = std::max(hi[k], r);
    }
  }
  else if (model.surface) {
    // Any other surface (cylinder, torus, height field, ...): mesh its own
    // chart x(u, v) over the parameter box the path visits, padded by about
    // 3R on the surface, with checker cells of about R.
    const geometry::Surface& surface = *model.surface;
    const geometry::ParameterDomain domain = surface.domain();
    double u0 = 1e300, u1 = -1e300, v0 = 1e300, v1 = -1e300, speedU = 0.0, speedV = 0.0;
    int found = 0;
    for (std::size_t i = 0; i < pathPoints_.size(); i += std::max<std::size_t>(1, pathPoints_.size() / 200)) {
      const auto uv = surface.parametersOf(pathPoints_[i]);
      if (!uv) continue;
      u0 = std::min(u0, uv->x());
      u1 = std::max(u1, uv->x());
      v0 = std::min(v0, uv->y());
      v1 = std::max(v1, uv->y());
      const geometry::SurfaceJet j = surface.jet(*uv);
      speedU += j.xu.norm();
      speedV += j.xv.norm();
      ++found;
    }
    if (found > 0) {
      speedU = std::max(speedU / found, 1e-9);
      speedV = std::max(speedV / found, 1e-9);
      const double eps = 1e-6;
      u0 = std::max(u0 - 3.0 * R / speedU, domain.uMin + eps);
      u1 = std::min(u1 + 3.0 * R / speedU, domain.uMax - eps);
      v0 = std::max(v0 - 3.0 * R / speedV, domain.vMin + eps);
      v1 = std::min(v1 + 3.0 * R / speedV, domain.vMax - eps);
      const auto cellsU = float((u1 - u0) * speedU / R), cellsV = float((v1 - v0) * speedV / R);
      surfaceMesh_ = render::parametricPatch(
          [&](float a, float b, glm::vec3& p, glm::vec3& nn) {
            const geometry::Vec2 uv(u0 + (u1 - u0) * a, v0 + (v1 - v0) * b);
            p = toGlm(surface.position(uv));
            nn = toGlm(surface.normal(uv));
          },
          std::clamp(int(cellsU * 4), 16, 256), std::clamp(int(cellsV * 4), 16, 256), glm::vec2(cellsU, cellsV));
      surfaceMaterial_.color = {0.78f, 0.77f, 0.74f};
      surfaceMaterial_.color2 = {0.55f, 0.57f, 0.60f};
      for (const auto& v : surfaceMesh_->vertices) {
        const Vec3 p(v.position.x, v.position.y, v.position.z);
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
      }
    }
  }
  if (model.plate) {
    // Brockett's plate translates with the top point: on a plane the top
    // moves contactSpeedRatio (= 2) times as fast as the contact point, so
    // the plate point above the circle's centre-opposite point traces the
    // circle of radius R1 about the contact circle's centre.
    discMesh_ = render::unitCylinder(96);
    const double kg = start.geodesicCurvature;
    plateCircleCentre_ = std::abs(kg) > 1e-12 ? Vec3(start.point + start.tangentNormal / kg) : Vec3(start.point);
    hi = hi.cwiseMax(model.plate->initialTopPoint + 0.2 * R * start.normal.cwiseAbs());
    const std::size_t pathFramePoints = framePoints_.size();
    for (std::size_t i = 0; i < pathFramePoints; ++i) framePoints_.push_back(framePoints_[i] + 1.2 * R * start.normal);
    // The glass disc reaches beyond the path (the plate's marked point
    // circles at R1 = 2r): its rim, wherever the plate moves, must stay in
    // frame and inside the far plane.
    for (int i = 0; i < 24; ++i) {
      const double s = length * i / 24.0;
      const geometry::DarbouxSample f = model.path->at(s);
      const Vec3 e1 = geometry::defaultTangentFor(f.normal), e2 = f.normal.cross(e1);
      const auto [centre, radius] = plateDisc(s);
      for (int k = 0; k < 16; ++k) {
        const double phi = 2.0 * std::numbers::pi * k / 16.0;
        const Vec3 p = centre + radius * (std::cos(phi) * e1 + std::sin(phi) * e2) + 0.1 * R * f.normal;
        framePoints_.push_back(p);
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
      }
    }
  }
  frameCentre_ = 0.5 * (lo + hi);
  frameRadius_ = 0.5 * (hi - lo).norm();

}

namespace {

struct CameraSetup {
  render::View view;
  OrbitAngles angles;
};

render::Light keyLight(const glm::vec3& up, const glm::vec3& eyeDirection, const glm::vec3& centre, float radius) {
  render::Light light;
  const glm::vec3 side = glm::normalize(glm::cross(glm::vec3(0, 0, 1), eyeDirection) + glm::vec3(1e-6f, 0, 0));
  // Upper left, slightly in front of the subject: a classic key light.
  light.towardLight = glm::normalize(up * 1.0f + eyeDirection * 0.35f - side * 0.5f);
  light.shadowCenter = centre;
  light.shadowRadius = radius;
  return light;
}

render::View orbitView(int x, int y, int w, int h, const glm::vec3& target, double distance, const OrbitAngles& a,
                       double fovDeg, double sceneRadius) {
  render::View v;
  v.x = x;
  v.y = y;
  v.width = w;
  v.height = h;
  const glm::vec3 dir(float(std::cos(a.elevation) * std::cos(a.azimuth)),
                      float(std::cos(a.elevation) * std::sin(a.azimuth)), float(std::sin(a.elevation)));
  const glm::vec3 eye = target + float(distance) * dir;
  v.camera.position = eye;
  v.camera.viewFromWorld = glm::lookAt(eye, target, glm::vec3(0, 0, 1));
  const float nearPlane = float(std::max(0.02 * distance, distance - 2.5 * sceneRadius));
  const float farPlane = float(distance + 4.0 * sceneRadius);
  v.camera.clipFromView = glm::perspective(float(fovDeg * kDeg), float(w) / float(std::max(h, 1)), nearPlane, farPlane);
  return v;
}

// Distance at which a sphere of radius r fills the smaller field of view.
double fitDistance(double radius, double fovDeg, double aspect) {
  const double halfV = 0.5 * fovDeg * kDeg;
  const double halfH = std::atan(std::tan(halfV) * aspect);
  return radius / std::sin(std::min(halfV, halfH)) * 1.04;
}

// Target and distance that keep every point (padded by `pad`) inside the
// field of view, seen from the orbit direction: each point needs
// D ≥ depth + |offset| / tan(half-angle) along both image axes.
std::pair<Vec3, double> fitPoints(const std::vector<Vec3>& points, double pad, const OrbitAngles& a, double fovDeg,
                                  double aspect) {
  const Vec3 toEye(std::cos(a.elevation) * std::cos(a.azimuth), std::cos(a.elevation) * std::sin(a.azimuth),
                   std::sin(a.elevation));
  const Vec3 right = Vec3::UnitZ().cross(toEye).normalized();
  const Vec3 up = toEye.cross(right);
  Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
  for (const Vec3& p : points) {
    const Vec3 c(p.dot(right), p.dot(up), p.dot(toEye));
    lo = lo.cwiseMin(c);
    hi = hi.cwiseMax(c);
  }
  const Vec3 mid = 0.5 * (lo + hi);
  Vec3 target = mid.x() * right + mid.y() * up + mid.z() * toEye;
  const double tanV = std::tan(0.5 * fovDeg * kDeg), tanH = tanV * aspect;
  double distance = 0.0;
  // Perspective makes near points take more room: re-centre on the projected
  // extent a few times (converges quickly; deterministic).
  for (int iteration = 0; iteration < 4; ++iteration) {
    distance = 0.0;
    for (const Vec3& p : points) {
      const Vec3 d = p - target;
      const double depth = d.dot(toEye) + pad;
      distance = std::max({distance, depth + (std::abs(d.dot(right)) + pad) / tanH,
                           depth + (std::abs(d.dot(up)) + pad) / tanV});
    }
    double xLo = 1e300, xHi = -1e300, yLo = 1e300, yHi = -1e300;
    for (const Vec3& p : points) {
      const Vec3 d = p - target;
      const double w = distance - d.dot(toEye);
      xLo = std::min(xLo, (d.dot(right) - pad) / w);
      xHi = std::max(xHi, (d.dot(right) + pad) / w);
      yLo = std::min(yLo, (d.dot(up) - pad) / w);
      yHi = std::max(yHi, (d.dot(up) + pad) / w);
    }
    target += distance * (0.5 * (xLo + xHi) * right + 0.5 * (yLo + yHi) * up);
  }
  return {target, distance * 1.03};
}

OrbitAngles orbitAngles(const scene::SceneSpec& spec, const RollingModel& model) {
  OrbitAngles a{spec.render.azimuthDeg * kDeg, spec.render.elevationDeg * kDeg};
  const bool azimuthGiven = spec.locations.contains("render.azimuth_deg");
  const bool elevationGiven = spec.locations.contains("render.elevation_deg");
  if (const auto* plane = dynamic_cast<const geometry::Plane*>(model.surface.get())) {
    const Vec3 n = plane->normal();
    if (std::abs(n.z()) < 0.5) {
      // A wall: look at it from its side, a little from above.
      if (!azimuthGiven) a.azimuth = std::atan2(n.y(), n.x()) - 25.0 * kDeg;
      if (!elevationGiven) a.elevation = 14.0 * kDeg;
    } else if (spec.render.strobe > 1 && !elevationGiven) {
      // From high up: seen at 40° the positions on the far and near sides of
      // a circle overlap (eight around the lollipop circle are 2.4R apart,
      // foreshortened to 1.5R); at 70° they stand apart.
      a.elevation = 70.0 * kDeg;
    } else if (n.z() < 0.0 && !elevationGiven) {
      a.elevation = -a.elevation;  // a ceiling: look from below
    }
  }
  return a;
}

}  // namespace

SceneDrawer::Aim SceneDrawer::aimOf(const Shot& shot, int w, int h, double s) const {
  const OrbitAngles a{shot.azimuth, shot.elevation};
  const double R = model_.ballRadius;
  const double aspect = double(w) / double(std::max(h, 1));
  auto [target, distance] = fitPoints(framePoints_, R, a, shot.fovDeg, aspect);
  if (shot.follow) {
    target = model_.path->at(s).centre(R);
    distance = fitDistance(4.0 * R, shot.fovDeg, aspect);
  }
  if (shot.target) target = *shot.target;
  if (shot.distance) distance = *shot.distance;
  return {target, distance, shot.azimuth, shot.elevation, shot.fovDeg};
}

SceneDrawer::Aim SceneDrawer::aimAt(const StoryPlace& story, int w, int h, double s) const {
  const std::size_t k = std::min(story.segment, shots_.size() - 1);
  const Aim to = aimOf(shots_[k], w, h, s);
  const double move = std::min(kCameraMove, story.duration);
  if (k == 0 || !(story.seconds < move)) return to;
  // On the way from the previous segment's camera: eased, the azimuth the
  // short way round. Equal cameras blend to themselves exactly.
  const Aim from = aimOf(shots_[k - 1], w, h, s);
  const double x = ease(scene::Easing::Smooth, story.seconds / move);
  auto mix = [x](double a, double b) { return a + (b - a) * x; };
  const double turn = std::remainder(to.azimuth - from.azimuth, 2.0 * std::numbers::pi);
  return {from.target + (to.target - from.target) * x, mix(from.distance, to.distance), from.azimuth + turn * x,
          mix(from.elevation, to.elevation), mix(from.fovDeg, to.fovDeg)};
}

render::View SceneDrawer::ballCamera(int x, int y, int w, int h, double s, const StoryPlace& story) const {
  const Aim aim = aimAt(story, w, h, s);
  const OrbitAngles a{aim.azimuth, aim.elevation};
  const double R = model_.ballRadius;
  const Vec3 target = aim.target;
  render::View v = orbitView(x, y, w, h, toGlm(target), aim.distance, a, aim.fovDeg, frameRadius_ + 3.0 * R);
  glm::vec3 up(0, 0, 1);
  if (const auto* plane = dynamic_cast<const geometry::Plane*>(model_.surface.get())) {
    up = toGlm(plane->normal());
    // A wall: light from the ceiling as well as from in front, so that the
    // ball's shadow falls below it on the wall, where it reads as a shadow,
    // not straight behind it as a dark rim around the ball.
    if (std::abs(up.z) < 0.7f) up = glm::normalize(up + glm::vec3(0.0f, 0.0f, 1.5f));
  }
  const glm::vec3 eyeDir = glm::normalize(v.camera.position - toGlm(target));
  // The shadow box hugs the ball (a strobe: all of them), see render::Light.
  if (spec_.render.strobe > 1) {
    v.light = keyLight(up, eyeDir, toGlm(frameCentre_), float(frameRadius_ + R));
  } else {
    v.light = keyLight(up, eyeDir, toGlm(model_.path->at(s).centre(R)), float(1.8 * R));
  }
  v.light.shadowSoftness = float(0.12 * R);
  v.light.shadow = spec_.render.shadow;
  return v;
}

render::DrawList SceneDrawer::draw(const FrameOrientations& frame) const {
  render::DrawList list;
  const auto& rs = spec_.render;
  list.width = static_cast<int>(rs.width);
  list.height = static_cast<int>(rs.height);
  list.msaaSamples = static_cast<int>(rs.msaa);
  list.transparent = rs.transparent;
  const int W = list.width, H = list.height;
  const float text = std::max(11.0f, float(H) / 42.0f);

  int top = 0;
  // A segment's title replaces render.title while it plays; the band stays
  // for the whole clip when any title is set, so the views never jump.
  const scene::SegmentSpec* segment =
      spec_.segments.empty() ? nullptr : &spec_.segments[std::min(frame.story.segment, spec_.segments.size() - 1)];
  const std::string& titleText = segment && segment->title ? *segment->title : rs.title;
  if (titleBand_) {
    top = static_cast<int>(std::lround(text * 2.4f));
    render::View band;
    band.width = W;
    band.height = top;
    band.backgroundBottom = band.backgroundTop;  // continues the views' top colour
    band.light.shadow = false;
    list.views.push_back(band);
    render::LabelItem title;
    title.text = titleText;
    title.anchor = glm::vec3(0.5f * W, 0.5f * top, 0.0f);
    title.align = render::Align::Center;
    title.sizePx = text * 1.35f;
    title.bold = true;
    title.color = kTextColor;
    if (!titleText.empty()) list.labels.push_back(title);
  }
  const int bodyHeight = H - top;
  switch (rs.layout) {
    case scene::RenderLayout::SideBySide: {
      const int ballWidth = static_cast<int>(std::lround(W * 0.6));
      list.views.push_back(ballCamera(0, top, ballWidth, bodyHeight, frame.current.s, frame.story));
      addBallView(list, frame, int(list.views.size()) - 1);
      addCaption(list, frame, int(list.views.size()) - 1);
      render::View twin;
      twin.x = ballWidth;
      twin.y = top;
      twin.width = W - ballWidth;
      twin.height = bodyHeight;
      list.views.push_back(twin);
      addTwinView(list, frame, int(list.views.size()) - 1);
      break;
    }
    case scene::RenderLayout::Inset: {
      list.views.push_back(ballCamera(0, top, W, bodyHeight, frame.current.s, frame.story));
      addBallView(list, frame, int(list.views.size()) - 1);
      addCaption(list, frame, int(list.views.size()) - 1);
      const int margin = static_cast<int>(std::lround(H * 0.025));
      const int side = static_cast<int>(std::lround(std::min(W, bodyHeight) * 0.42));
      render::View twin;
      twin.x = W - side - margin;
      twin.y = top + margin;
      twin.width = side;
      twin.height = side;
      twin.frame = true;
      list.views.push_back(twin);
      addTwinView(list, frame, int(list.views.size()) - 1);
      break;
    }
    case scene::RenderLayout::Ball:
      list.views.push_back(ballCamera(0, top, W, bodyHeight, frame.current.s, frame.story));
      addBallView(list, frame, int(list.views.size()) - 1);
      addCaption(list, frame, int(list.views.size()) - 1);
      break;
    case scene::RenderLayout::Twin: {
      render::View twin;
      twin.y = top;
      twin.width = W;
      twin.height = bodyHeight;
      list.views.push_back(twin);
      addTwinView(list, frame, int(list.views.size()) - 1);
      addCaption(list, frame, int(list.views.size()) - 1);
      break;
    }
  }
  return list;
}

// A storyboard segment's caption, centred under the view's heading row. It
// is the lecturer's own text, so it shows even with render.labels = false.
void SceneDrawer::addCaption(render::DrawList& list, const FrameOrientations& frame, int view) const {
  if (spec_.segments.empty()) return;
  const std::string& caption = spec_.segments[std::min(frame.story.segment, spec_.segments.size() - 1)].caption;
  if (caption.empty()) return;
  const render::View& v = list.views[static_cast<std::size_t>(view)];
  const float text = std::max(11.0f, float(list.height) / 42.0f);
  render::LabelItem label;
  label.view = view;
  label.text = caption;
  label.anchor = glm::vec3(0.5f * float(v.width), text * 0.8f + text * 2.1f, 0.0f);
  label.align = render::Align::Center;
  label.sizePx = sizeToFit({caption}, float(v.width) - 1.6f * text, text * 1.2f, true);
  label.bold = true;
  label.color = glm::vec4(0.55f, 0.12f, 0.02f, 1.0f);
  list.labels.push_back(label);
}

void SceneDrawer::addBallView(render::DrawList& list, const FrameOrientations& frame, int view) const {
  const double R = model_.ballRadius;
  const double s = frame.current.s;
  const float text = std::max(11.0f, float(list.height) / 42.0f);
  const render::View& v = list.views[static_cast<std::size_t>(view)];

  if (surfaceMesh_) list.meshes.push_back({surfaceMesh_, glm::mat4(1.0f), surfaceMaterial_, view});
  if (!cutRim_.empty()) {
    render::PolylineItem rim;
    rim.color = glm::vec4(0.25f, 0.27f, 0.30f, 1.0f);
    rim.widthPx = std::max(1.2f, float(list.height) / 450.0f);
    rim.view = view;
    for (const Vec3& p : cutRim_) rim.points.push_back(toGlm(p));
    list.polylines.push_back(rim);
  }

  // The contact path, lifted a hair along the normal; travelled part on top.
  render::PolylineItem full, travelled;
  full.color = kPathColor;
  full.widthPx = std::max(1.5f, float(list.height) / 400.0f);
  travelled.color = kTravelledColor;
  travelled.widthPx = std::max(2.5f, float(list.height) / 200.0f);
  full.view = travelled.view = view;
  travelled.dynamic = true;  // grows with s: redrawn per frame over the retained layer
  for (std::size_t i = 0; i < pathS_.size(); ++i) {
    const Vec3 p = pathPoints_[i] + 0.004 * R * model_.path->normal(pathS_[i]);
    full.points.push_back(toGlm(p));
    if (pathS_[i] <= s) travelled.points.push_back(toGlm(p));
  }
  travelled.points.push_back(toGlm(model_.path->point(s) + 0.004 * R * model_.path->normal(s)));
  list.polylines.push_back(full);
  list.polylines.push_back(travelled);

  // The ball(s): texture in body coordinates, rotated by worldFromBody.
  render::Material ballMaterial;
  ballMaterial.pattern = render::Pattern::Texture;
  ballMaterial.texture = ballTexture_;
  ballMaterial.color = glm::vec3(1.0f);
  ballMaterial.specular = 0.12f;
  ballMaterial.shininess = 24.0f;
  render::Material markerMaterial;
  markerMaterial.color = kMarkerColor;
  markerMaterial.specular = 0.5f;
  markerMaterial.shininess = 80.0f;
  auto addBall = [&](const OrientedSample& pose) {
    const Vec3 c = model_.path->at(pose.s).centre(R);
    const glm::mat4 worldFromBody = rotationOf(pose.q);
    list.meshes.push_back({sphereMesh_,
                           glm::translate(glm::mat4(1.0f), toGlm(c)) * worldFromBody * glm::scale(glm::mat4(1.0f), glm::vec3(float(R))),
                           ballMaterial, view});
    list.meshes.back().dynamic = true;
    const Vec3 marker = c + 0.97 * R * pose.q.rotate(markerBody_);
    list.meshes.push_back({dotMesh_,
                           glm::translate(glm::mat4(1.0f), toGlm(marker)) * glm::scale(glm::mat4(1.0f), glm::vec3(float(0.13 * R))),
                           markerMaterial, view});
    list.meshes.back().dynamic = true;
  };
  if (frame.strobe.empty()) {
    addBall(frame.current);
  } else {
    for (const auto& pose : frame.strobe) addBall(pose);
  }

  // The marker's path through space: cusps where it touches the surface.
  if (frame.trail.size() >= 2) {
    render::PolylineItem markerTrail;
    markerTrail.color = glm::vec4(kMarkerColor, 0.55f);
    markerTrail.widthPx = std::max(1.2f, float(list.height) / 500.0f);
    markerTrail.view = view;
    markerTrail.dynamic = true;
    for (const auto& t : frame.trail)
      markerTrail.points.push_back(toGlm(model_.path->at(t.s).centre(R) + R * t.q.rotate(markerBody_)));
    list.polylines.push_back(markerTrail);
  }

  if (model_.plate && frame.strobe.empty()) {
    const geometry::DarbouxSample f = model_.path->at(s);
    const double thickness = 0.08 * R;
    // The plate point above the circle's far side traces the circle of
    // radius R1 = ratio · r about the contact circle's centre.
    const Vec3 plateCentre = platePoint(s, 0.0);
    const auto [discCentre, discRadius] = plateDisc(s);
    const glm::vec3 n = toGlm(f.normal);
    const glm::vec3 e1 = toGlm(geometry::defaultTangentFor(f.normal)), e2 = glm::cross(n, e1);
    glm::mat4 disc(1.0f);
    disc[0] = glm::vec4(e1 * float(discRadius), 0.0f);
    disc[1] = glm::vec4(e2 * float(discRadius), 0.0f);
    disc[2] = glm::vec4(n * float(thickness), 0.0f);
    disc[3] = glm::vec4(toGlm(discCentre), 1.0f);
    render::Material glass;
    glass.color = {0.55f, 0.80f, 0.95f};
    glass.opacity = 0.14f;
    glass.specular = 0.9f;
    glass.shininess = 120.0f;
    glass.castsShadow = false;
    list.meshes.push_back({discMesh_, disc, glass, view});
    list.meshes.back().dynamic = true;  // the plate moves with the ball
    render::PolylineItem rim;  // the glass edge, so the plate reads as a sheet
    rim.color = glm::vec4(0.85f, 0.95f, 1.0f, 0.9f);
    rim.widthPx = std::max(1.2f, float(list.height) / 450.0f);
    rim.view = view;
    rim.dynamic = true;
    for (int k = 0; k <= 128; ++k) {
      const float phi = 2.0f * std::numbers::pi_v<float> * float(k) / 128.0f;
      rim.points.push_back(glm::vec3(disc * glm::vec4(std::cos(phi), std::sin(phi), 1.0f, 1.0f)));
    }
    list.polylines.push_back(rim);
    // The plate's own marker: a dot at its centre, and the circle it traces.
    render::Material dot;
    dot.color = {0.35f, 0.10f, 0.55f};
    glm::mat4 dotModel(1.0f);
    dotModel[0] = glm::vec4(e1 * float(0.12 * R), 0.0f);
    dotModel[1] = glm::vec4(e2 * float(0.12 * R), 0.0f);
    dotModel[2] = glm::vec4(n * float(0.02 * R), 0.0f);
    dotModel[3] = glm::vec4(toGlm(plateCentre + thickness * f.normal), 1.0f);
    list.meshes.push_back({discMesh_, dotModel, dot, view});
    list.meshes.back().dynamic = true;
    render::PolylineItem plateTrail;
    plateTrail.color = glm::vec4(dot.color, 0.7f);
    plateTrail.widthPx = std::max(1.2f, float(list.height) / 450.0f);
    plateTrail.view = view;
    plateTrail.dynamic = true;
    for (std::size_t i = 0; i < pathS_.size(); ++i) {
      if (pathS_[i] > s) break;
      plateTrail.points.push_back(toGlm(platePoint(pathS_[i], thickness * 1.05)));
    }
    list.polylines.push_back(plateTrail);
  }
  if (facts_ && facts_->marks) addMarks(list, s, frame.strobe.empty(), view);

  if (spec_.render.labels) {
    const float margin = text * 0.8f;
    render::LabelItem heading;
    heading.view = view;
    heading.text = frame.strobe.empty() ? "rolling ball" : fmt::format("rolling ball at {} positions", frame.strobe.size());
    heading.anchor = glm::vec3(margin, margin, 0.0f);
    heading.sizePx = text * 1.1f;
    heading.bold = true;
    heading.color = kTextColor;
    list.labels.push_back(heading);
    const spin::AngleAxis aa = spin::rotationAngleAxis(frame.current.q);
    const double psi = spin::spinorAngle(frame.current.q);
    const std::vector<std::string> lines{
        fmt::format("s = {:.2f} of {:.2f}", s, model_.path->length()),
        fmt::format("rotation angle = {:.1f}°", aa.angle / kDeg),
        fmt::format("spinor angle ψ = {:.1f}°", psi / kDeg)};
    for (std::size_t i = 0; i < lines.size() && frame.strobe.empty(); ++i) {
      render::LabelItem l;
      l.view = view;
      l.dynamic = true;  // s and the angles
      l.text = lines[i];
      l.anchor = glm::vec3(margin, float(v.height) - margin - float(lines.size() - 1 - i) * text * 1.35f - 0.4f * text, 0.0f);
      l.sizePx = text;
      l.color = kTextColor;
      list.labels.push_back(l);
    }
    if (facts_) addFactLabels(list, frame, view, margin + text * 2.0f);
  }
}

Vec3 SceneDrawer::platePoint(double s, double lift) const {
  const geometry::DarbouxSample f = model_.path->at(s);
  return plateCircleCentre_ + model_.plate->contactSpeedRatio * (f.point - plateCircleCentre_) +
         (2.0 * model_.ballRadius + lift) * f.normal;
}

// Centred between the marked point and the ball's top (the plate is an
// unbounded plane; a disc around both keeps the picture, and its framing,
// as small as they can be), with a margin of 0.8 R.
std::pair<Vec3, double> SceneDrawer::plateDisc(double s) const {
  const geometry::DarbouxSample f = model_.path->at(s);
  const Vec3 marked = platePoint(s, 0.0);
  const Vec3 top = f.point + 2.0 * model_.ballRadius * f.normal;
  return {0.5 * (marked + top), 0.5 * (marked - top).norm() + 0.8 * model_.ballRadius};
}

// The marks every β of path angle: dots on the contact path (dark once
// passed) and, where the plate is drawn (not in a strobe), on its trail;
// numbered.
void SceneDrawer::addMarks(render::DrawList& list, double s, bool plateShown, int view) const {
  const double R = model_.ballRadius;
  const float text = std::max(11.0f, float(list.height) / 42.0f);
  const MarksFact& m = *facts_->marks;
  const int passed = facts_->marksPassed(s);
  // Labels are drawn over everything: leave out a number the ball hides
  // (its segment from the eye to the mark passes through the ball).
  const Vec3 eye(list.views[static_cast<std::size_t>(view)].camera.position.x,
                 list.views[static_cast<std::size_t>(view)].camera.position.y,
                 list.views[static_cast<std::size_t>(view)].camera.position.z);
  const Vec3 ball = model_.path->at(s).centre(R);
  auto hiddenByBall = [&](const Vec3& p) {
    const Vec3 d = p - eye;
    const double t = std::clamp((ball - eye).dot(d) / d.squaredNorm(), 0.0, 1.0);
    return (eye + t * d - ball).norm() < R && t < 1.0;
  };
  for (std::size_t k = 0; k < m.s.size(); ++k) {
    const bool done = int(k) < passed;
    render::Material dot;
    dot.color = done ? glm::vec3(0.05f, 0.05f, 0.08f) : glm::vec3(0.45f, 0.45f, 0.5f);
    dot.castsShadow = false;
    const geometry::DarbouxSample f = model_.path->at(m.s[k]);
    const Vec3 onPath = f.point + 0.02 * R * f.normal;
    list.meshes.push_back({dotMesh_,
                           glm::translate(glm::mat4(1.0f), toGlm(onPath)) * glm::scale(glm::mat4(1.0f), glm::vec3(float(0.06 * R))),
                           dot, view});
    list.meshes.back().figureDisc = true;  // a vector disc in PDF/SVG figures
    if (model_.plate && plateShown && done) {
      const Vec3 onPlate = platePoint(m.s[k], 0.06 * R);
      list.meshes.push_back({dotMesh_,
                             glm::translate(glm::mat4(1.0f), toGlm(onPlate)) * glm::scale(glm::mat4(1.0f), glm::vec3(float(0.05 * R))),
                             dot, view});
      list.meshes.back().figureDisc = true;
    }
    if (!spec_.render.labels || (plateShown && hiddenByBall(onPath))) continue;
    render::LabelItem number;
    number.view = view;
    number.text = fmt::format("{}", k);
    // Outward from the circle's centre, so the number sits beside the path.
    // Outward: u = n × t points to the centre where κ_g > 0.
    number.anchor = toGlm(onPath - std::copysign(0.4 * R, f.geodesicCurvature) * f.tangentNormal);
    number.worldAnchored = true;
    number.align = render::Align::Center;
    number.sizePx = text * 0.9f;
    number.bold = true;
    number.color = done ? kTextColor : glm::vec4(0.12f, 0.13f, 0.16f, 1.0f);
    list.labels.push_back(number);
  }
}

// The scene's facts (draw_facts formats them) under the view's heading.
void SceneDrawer::addFactLabels(render::DrawList& list, const FrameOrientations& frame, int view, float top) const {
  const float text = std::max(11.0f, float(list.height) / 42.0f);
  const float margin = text * 0.8f;
  const std::vector<std::string> lines = factLines(*facts_, frame, model_.path->length());
  const float size =
      sizeToFit(lines, float(list.views[static_cast<std::size_t>(view)].width) - 2.0f * margin, text * 0.9f, false);
  for (std::size_t i = 0; i < lines.size(); ++i) {
    render::LabelItem l;
    l.view = view;
    l.dynamic = true;  // live values
    l.text = lines[i];
    l.anchor = glm::vec3(margin, top + float(i) * size * 1.45f, 0.0f);
    l.sizePx = size;
    l.color = kTextColor;
    list.labels.push_back(l);
  }
}

void SceneDrawer::addTwinView(render::DrawList& list, const FrameOrientations& frame, int view) const {
  render::View& v = list.views[static_cast<std::size_t>(view)];
  const float text = std::max(11.0f, float(list.height) / 42.0f);
  // Same viewing direction as the ball's camera, so the marker on the ball
  // and the Bloch arrow point the same way on screen.
  const Aim aim = aimAt(frame.story, v.width, v.height, frame.current.s);
  const OrbitAngles a{aim.azimuth, aim.elevation};
  const double aspect = double(v.width) / double(std::max(v.height, 1));
  const double sceneRadius = 1.42;
  render::View oriented = orbitView(v.x, v.y, v.width, v.height, glm::vec3(0.0f, 0.0f, -0.04f),
                                    fitDistance(sceneRadius, aim.fovDeg, aspect), a, aim.fovDeg, sceneRadius);
  v.camera = oriented.camera;
  v.light = keyLight(glm::vec3(0, 0, 1), glm::normalize(v.camera.position), glm::vec3(0.0f), 1.5f);
  v.light.shadow = false;
  v.light.ambient = 0.45f;
  if (v.frame) {
    v.backgroundTop = glm::vec3(0.97f, 0.98f, 0.99f);
    v.backgroundBottom = glm::vec3(0.86f, 0.89f, 0.93f);
  }

  const auto& blochSphere = blochSphereMesh_;
  render::Material glass;
  glass.color = {0.62f, 0.76f, 0.95f};
  glass.opacity = 0.16f;
  glass.specular = 0.5f;
  glass.shininess = 90.0f;
  glass.castsShadow = false;
  list.meshes.push_back({blochSphere, glm::mat4(1.0f), glass, view});
  render::Material origin;
  origin.color = {0.2f, 0.2f, 0.22f};
  list.meshes.push_back({dotMesh_, glm::scale(glm::mat4(1.0f), glm::vec3(0.035f)), origin, view});

  // Equator and two meridians, and the axes.
  const glm::vec4 gridColor{0.30f, 0.36f, 0.45f, 0.75f};
  const float gridWidth = std::max(1.0f, float(list.height) / 600.0f);
  for (int circle = 0; circle < 3; ++circle) {
    render::PolylineItem c;
    c.color = gridColor;
    c.widthPx = gridWidth;
    c.view = view;
    for (int i = 0; i <= 180; ++i) {
      const float t = 2.0f * std::numbers::pi_v<float> * float(i) / 180.0f;
      const float x = std::cos(t), y = std::sin(t);
      c.points.push_back(circle == 0 ? glm::vec3(x, y, 0) : circle == 1 ? glm::vec3(x, 0, y) : glm::vec3(0, x, y));
    }
    list.polylines.push_back(c);
  }
  const glm::vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const char* axisNames[3] = {"x", "y", "z"};
  for (int k = 0; k < 3; ++k) {
    render::PolylineItem axis;
    axis.color = glm::vec4(0.15f, 0.17f, 0.2f, 0.9f);
    axis.widthPx = gridWidth;
    axis.view = view;
    axis.points = {-1.18f * axes[k], 1.18f * axes[k]};
    list.polylines.push_back(axis);
  }

  auto unit = [](const Vec3& x) { return x.norm() > 1e-12 ? Vec3(x.normalized()) : Vec3(Vec3::Zero()); };
  const double R = model_.ballRadius;
  auto fieldDirection = [&](double s) { return unit(spin::fieldB(model_.path->at(s), R)); };
  const float arrowRadius = 0.028f;

  // Trails: the Bloch vector X(s') = Q(s') X(0) and the field direction.
  render::PolylineItem blochTrail, fieldTrail;
  blochTrail.color = glm::vec4(kMarkerColor, 0.85f);
  fieldTrail.color = glm::vec4(kFieldColor, 0.7f);
  blochTrail.widthPx = fieldTrail.widthPx = std::max(1.5f, float(list.height) / 360.0f);
  blochTrail.view = fieldTrail.view = view;
  blochTrail.dynamic = fieldTrail.dynamic = true;
  for (const auto& t : frame.trail) {
    blochTrail.points.push_back(toGlm(t.q.rotate(markerBody_)));
    const Vec3 b = fieldDirection(t.s);
    if (b.norm() > 0.5) fieldTrail.points.push_back(toGlm(b));
  }
  list.polylines.push_back(fieldTrail);
  list.polylines.push_back(blochTrail);
  if (fieldConeMesh_) {
    // The cone B̂ sweeps over the whole circuit: its solid angle is Berry's phase.
    render::Material cone;
    cone.color = kFieldColor;
    cone.opacity = 0.18f;
    cone.lit = false;
    cone.castsShadow = false;
    cone.cull = render::Cull::None;
    list.meshes.push_back({fieldConeMesh_, glm::mat4(1.0f), cone, view});
  }

  const Vec3 x = frame.current.q.rotate(markerBody_);
  list.arrows.push_back({glm::vec3(0.0f), toGlm(x), arrowRadius, kMarkerColor, view, true});
  const Vec3 b = fieldDirection(frame.current.s);
  if (b.norm() > 0.5) list.arrows.push_back({glm::vec3(0.0f), toGlm(b), arrowRadius * 0.8f, kFieldColor, view, true});
  for (const auto& pose : frame.strobe)
    list.arrows.push_back({glm::vec3(0.0f), toGlm(pose.q.rotate(markerBody_)), arrowRadius * 0.55f,
                           glm::mix(kMarkerColor, glm::vec3(1.0f), 0.35f), view});

  if (spec_.render.labels) {
    auto worldLabel = [&](const std::string& s, const glm::vec3& at, float size, glm::vec4 color) {
      render::LabelItem l;
      l.view = view;
      l.text = s;
      l.anchor = at;
      l.worldAnchored = true;
      l.align = render::Align::Center;
      l.sizePx = size;
      l.color = color;
      list.labels.push_back(l);
    };
    for (int k = 0; k < 3; ++k) worldLabel(axisNames[k], 1.3f * axes[k], text, kTextColor);
    worldLabel("|0⟩", glm::vec3(0, 0, 1.0f), text, kTextColor);
    worldLabel("|1⟩", glm::vec3(0, 0, -1.0f), text, kTextColor);
    list.labels.back().offsetPx = glm::vec2(1.6f * text, 0.0f);
    list.labels[list.labels.size() - 2].offsetPx = glm::vec2(1.6f * text, 0.0f);

    const float margin = text * 0.8f;
    render::LabelItem heading;
    heading.view = view;
    heading.text = "Bloch sphere";
    heading.anchor = glm::vec3(margin, margin, 0.0f);
    heading.sizePx = text * 1.1f;
    heading.bold = true;
    heading.color = kTextColor;
    if (!v.frame) list.labels.push_back(heading);  // an inset has no room for it
    const std::pair<std::string, glm::vec3> legend[2] = {{"● spin  X(s) = Q(s) X(0)", kMarkerColor},
                                                         {"● field  B/|B|", kFieldColor}};
    for (int i = 0; i < 2 && !v.frame; ++i) {  // an inset is too small for a legend
      render::LabelItem l;
      l.view = view;
      l.text = legend[i].first;
      l.anchor = glm::vec3(margin, float(v.height) - margin - float(1 - i) * text * 1.35f - 0.4f * text, 0.0f);
      l.sizePx = text;
      l.color = glm::vec4(legend[i].second, 1.0f);
      list.labels.push_back(l);
    }
  }
}

}  // namespace rollspin::draw
