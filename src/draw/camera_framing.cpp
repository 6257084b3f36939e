#include "draw/camera_framing.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/gtc/matrix_transform.hpp>

#include "draw/draw_style.hpp"

namespace rollspin::draw {

using geometry::Vec3;
using motion::StoryPlace;

Vec3 towardEye(const OrbitAngles& a) {
  return {std::cos(a.elevation) * std::cos(a.azimuth), std::cos(a.elevation) * std::sin(a.azimuth),
          std::sin(a.elevation)};
}

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

Lens windowLens(const NdcWindow& window, double fovDeg, double aspect) {
  const double tanV = std::tan(0.5 * fovDeg * kDeg), tanH = tanV * aspect;
  const double windowTanV = 0.5 * (window.y1 - window.y0) * tanV, windowTanH = 0.5 * (window.x1 - window.x0) * tanH;
  return {2.0 * std::atan(windowTanV) / kDeg, windowTanH / windowTanV};
}

bool isWholeView(const NdcWindow& w) { return w.x0 == -1.0 && w.x1 == 1.0 && w.y0 == -1.0 && w.y1 == 1.0; }

glm::mat4 offAxisProjection(const NdcWindow& window, double fovDeg, double aspect, float nearPlane, float farPlane) {
  const double tanV = std::tan(0.5 * fovDeg * kDeg), tanH = tanV * aspect;
  const double cx = 0.5 * (window.x0 + window.x1), cy = 0.5 * (window.y0 + window.y1);
  return glm::frustum(float((-1.0 - cx) * tanH) * nearPlane, float((1.0 - cx) * tanH) * nearPlane,
                      float((-1.0 - cy) * tanV) * nearPlane, float((1.0 - cy) * tanV) * nearPlane, nearPlane, farPlane);
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

OrbitAngles orbitAngles(const scene::SceneSpec& spec, const model::RollingModel& model) {
  OrbitAngles a{spec.render.azimuthDeg * kDeg, spec.render.elevationDeg * kDeg};
  const bool azimuthGiven = spec.locations.contains("render.azimuth_deg");
  const bool elevationGiven = spec.locations.contains("render.elevation_deg");
  const geometry::SurfaceLook look = model.surface ? model.surface->look() : geometry::SurfaceLook{};
  if (look.orientedByUp) {
    const Vec3 n = look.up;
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

namespace {

// The least share, over the path, of the ball's disc that the eye sees past
// the surface as drawn (or any share below `useless`, once it is clear the
// least is that low). eyeAt(s): the eye at arc length s.
template <typename EyeAt>
double leastVisibleShare(const model::RollingModel& model, const SightLines& surface, const EyeAt& eyeAt,
                         double useless = 0.0) {
  const double R = model.ballRadius;
  double least = 1.0;
  for (int i = 0; i <= 48 && least >= useless && least > 0.0; ++i) {
    const double s = model.path->length() * i / 48.0;
    least = std::min(least, surface.visibleShare(eyeAt(s), model.path->at(s).centre(R), R));
  }
  return least;
}

// The share of the contact path the eye sees (points lifted a little off the
// surface, so that the mesh's chords under them do not count).
template <typename EyeAt>
double visiblePathShare(const model::RollingModel& model, const SightLines& surface, const EyeAt& eyeAt) {
  const double R = model.ballRadius;
  int seen = 0;
  for (int i = 0; i <= 96; ++i) {
    const double s = model.path->length() * i / 96.0;
    const geometry::DarbouxSample f = model.path->at(s);
    if (!surface.blocked(eyeAt(s), f.point + 0.05 * R * f.normal, 0.05 * R)) ++seen;
  }
  return seen / 97.0;
}

}  // namespace

// The default camera keeps the ball in sight: where the scene leaves the
// orbit angles free, try views round the given one (each step of turn
// costs) and, among those that see ≥ 96 % of the ball's disc at every place
// on the path (else ≥ 90 %), keep the one that sees most of the contact
// path less 5 % per step; the scene's own view when it sees ≥ 96 %. Where
// no still view does (a path round the back of a sphere), one that orbits
// with the ball's longitude. An inside sphere is cut open towards the eye
// (BallView), so its view already sees in.
OrbitAngles CameraFraming::unhiddenAngles(OrbitAngles base) {
  const bool cutOpen = model_.surface && model_.surface->look().cutAwayTowardEye;
  const bool azimuthFree = !spec_.locations.contains("render.azimuth_deg");
  const bool elevationFree = !spec_.locations.contains("render.elevation_deg");
  if (!extent_.surface || cutOpen || spec_.render.follow || (spec_.render.target && spec_.render.distance) ||
      !(azimuthFree || elevationFree))
    return base;
  const double aspect = double(spec_.render.width) / double(std::max<long long>(spec_.render.height, 1));
  const double R = model_.ballRadius;
  auto stillEye = [&](const OrbitAngles& a) {
    const auto [target, distance] = fitPoints(extent_.points, R, a, spec_.render.fovDeg, aspect);
    return Vec3(target + spec_.render.distance.value_or(distance) * towardEye(a));
  };

  struct Candidate {
    OrbitAngles angles;
    double cost;
  };
  std::vector<Candidate> candidates;
  const double below = base.elevation < 0.0 ? -1.0 : 1.0;  // a view from below stays below
  for (const double turn : {0.0, 30.0, -30.0, 60.0, -60.0, 90.0, -90.0, 135.0, -135.0, 180.0}) {
    if (turn != 0.0 && !azimuthFree) break;
    for (const double degrees : {0.0, 35.0, 45.0, 55.0, 65.0, 75.0}) {
      if (degrees != 0.0 && !elevationFree) break;
      const double elevation = below * std::max(below * base.elevation, degrees * kDeg);
      if (degrees != 0.0 && elevation == base.elevation) continue;
      candidates.push_back({{base.azimuth + turn * kDeg, elevation},
                            std::abs(turn) / 30.0 + std::abs(elevation - base.elevation) / kDeg / 10.0});
    }
  }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const Candidate& x, const Candidate& y) { return x.cost < y.cost; });
  // The share is sampled (25 rays, 49 places) for a full-view lens; the
  // text layout narrows the lens later and moves the eye a little, so a view
  // that sees ≥ 96 % is preferred to one that only just sees 90 %.
  struct Seen {
    const Candidate* candidate;
    double share, score;
  };
  std::vector<Seen> seen;
  const Candidate* leastHidden = nullptr;
  double bestShare = -1.0;
  for (const Candidate& c : candidates) {
    const Vec3 eye = stillEye(c.angles);
    auto eyeAt = [&](double) { return eye; };
    const double share = leastVisibleShare(model_, *extent_.surface, eyeAt, std::min(0.9, bestShare));
    if (share > bestShare + 1e-9) {
      bestShare = share;
      leastHidden = &c;
    }
    if (share >= 0.9)
      seen.push_back({&c, share, visiblePathShare(model_, *extent_.surface, eyeAt) - 0.05 * c.cost});
    if (share >= 0.96 && c.cost == 0.0) break;  // the scene's own view sees it all
  }
  for (const double enough : {0.96, 0.9}) {
    const Seen* chosen = nullptr;
    for (const Seen& v : seen)
      if (v.share >= enough && (chosen == nullptr || v.score > chosen->score + 1e-9)) chosen = &v;
    if (chosen) return chosen->candidate->angles;
  }

  if (azimuthFree && spec_.segments.empty()) {
    // The ball's longitude about the z axis at s.
    auto longitude = [&](double s) {
      const Vec3 p = model_.path->at(s).point;
      return std::atan2(p.y(), p.x());
    };
    const double offset = base.azimuth - longitude(0.0);
    for (const double degrees : {0.0, 35.0, 45.0, 55.0, 65.0, 75.0}) {
      if (degrees != 0.0 && !elevationFree) break;
      const double elevation = below * std::max(below * base.elevation, degrees * kDeg);
      auto eyeAt = [&](double s) { return stillEye({longitude(s) + offset, elevation}); };
      const double share = leastVisibleShare(model_, *extent_.surface, eyeAt);
      if (share > bestShare + 1e-9) {
        orbitOffset_ = offset;
        orbits_ = true;
        bestShare = share;
        base.elevation = elevation;
      }
      if (share >= 0.9) return base;
    }
    if (orbits_) return base;
  }
  return leastHidden ? leastHidden->angles : base;
}

CameraFraming::CameraFraming(const scene::SceneSpec& spec, const model::RollingModel& model, FrameExtent extent)
    : spec_(spec), model_(model), extent_(std::move(extent)) {
  const OrbitAngles base = unhiddenAngles(orbitAngles(spec, model));
  Shot shot{base.azimuth, base.elevation, spec.render.fovDeg, std::nullopt, spec.render.distance, spec.render.follow};
  if (spec.render.target) shot.target = Vec3((*spec.render.target)[0], (*spec.render.target)[1], (*spec.render.target)[2]);
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
  }
  if (shots_.empty()) shots_.push_back(shot);
}

bool CameraFraming::fixedByScene() const {
  return std::all_of(shots_.begin(), shots_.end(), [](const Shot& s) { return s.follow || (s.target && s.distance); });
}

CameraFraming::Aim CameraFraming::aimOf(const Shot& shot, int w, int h, double s) const {
  OrbitAngles a{shot.azimuth, shot.elevation};
  if (orbits_) {  // with the ball round the sphere (see the constructor)
    const Vec3 p = model_.path->at(s).point;
    a.azimuth = std::atan2(p.y(), p.x()) + orbitOffset_;
  }
  const double R = model_.ballRadius;
  // Fit into the window: a narrower field of view about its centre (the
  // projection is shifted off axis to put that centre there, ballCamera).
  const Lens lens = windowLens(window_, shot.fovDeg, double(w) / double(std::max(h, 1)));
  const double fovDeg = lens.fovDeg, aspect = lens.aspect;
  auto [target, distance] = fitPoints(extent_.points, R, a, fovDeg, aspect);
  if (shot.follow) {
    target = model_.path->at(s).centre(R);
    distance = fitDistance(4.0 * R, fovDeg, aspect);
  }
  if (shot.target) target = *shot.target;
  if (shot.distance) distance = *shot.distance;
  return {target, distance, a.azimuth, a.elevation, shot.fovDeg};
}

CameraFraming::Aim CameraFraming::aimAt(const StoryPlace& story, int w, int h, double s) const {
  const std::size_t k = std::min(story.segment, shots_.size() - 1);
  const Aim to = aimOf(shots_[k], w, h, s);
  const double move = std::min(kCameraMove, story.duration);
  if (k == 0 || !(story.seconds < move)) return to;
  // On the way from the previous segment's camera: eased, the azimuth the
  // short way round. Equal cameras blend to themselves exactly.
  const Aim from = aimOf(shots_[k - 1], w, h, s);
  const double x = motion::ease(scene::Easing::Smooth, story.seconds / move);
  auto mix = [x](double a, double b) { return a + (b - a) * x; };
  const double turn = std::remainder(to.azimuth - from.azimuth, 2.0 * std::numbers::pi);
  return {from.target + (to.target - from.target) * x, mix(from.distance, to.distance), from.azimuth + turn * x,
          mix(from.elevation, to.elevation), mix(from.fovDeg, to.fovDeg)};
}

render::View CameraFraming::ballCamera(int x, int y, int w, int h, double s, const StoryPlace& story) const {
  const Aim aim = aimAt(story, w, h, s);
  const OrbitAngles a{aim.azimuth, aim.elevation};
  const double R = model_.ballRadius;
  const Vec3 target = aim.target;
  const double sceneRadius = extent_.radius + 3.0 * R;
  render::View v = orbitView(x, y, w, h, toGlm(target), aim.distance, a, aim.fovDeg, sceneRadius);
  if (!isWholeView(window_)) {
    // Off axis: the view's axis (through the target) meets the image at the
    // window's centre, not the view's.
    const float nearPlane = float(std::max(0.02 * aim.distance, aim.distance - 2.5 * sceneRadius));
    const float farPlane = float(aim.distance + 4.0 * sceneRadius);
    v.camera.clipFromView =
        offAxisProjection(window_, aim.fovDeg, double(w) / double(std::max(h, 1)), nearPlane, farPlane);
  }
  glm::vec3 up(0, 0, 1);
  if (const geometry::SurfaceLook look = model_.surface ? model_.surface->look() : geometry::SurfaceLook{};
      look.orientedByUp) {
    up = toGlm(look.up);
    // A wall: light from the ceiling as well as from in front, so that the
    // ball's shadow falls below it on the wall, where it reads as a shadow,
    // not straight behind it as a dark rim around the ball.
    if (std::abs(up.z) < 0.7f) up = glm::normalize(up + glm::vec3(0.0f, 0.0f, 1.5f));
  }
  const glm::vec3 eyeDir = glm::normalize(v.camera.position - toGlm(target));
  // The shadow box hugs the ball (a strobe: all of them), see render::Light.
  if (spec_.render.strobe > 1) {
    v.light = keyLight(up, eyeDir, toGlm(extent_.centre), float(extent_.radius + R));
  } else {
    v.light = keyLight(up, eyeDir, toGlm(model_.path->at(s).centre(R)), float(1.8 * R));
  }
  v.light.shadowSoftness = float(0.12 * R);
  v.light.shadow = spec_.render.shadow;
  return v;
}

}  // namespace rollspin::draw
