#include "draw/camera_framing.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <numbers>
#include <tuple>

#include "draw/draw_style.hpp"
#include "draw/screen_axes.hpp"
#include "motion/frame_clock.hpp"

namespace rollspin::draw {

using geometry::Vec3;
using motion::StoryPlace;

Vec3 towardEye(const OrbitAngles &a) {
  return {std::cos(a.elevation) * std::cos(a.azimuth), std::cos(a.elevation) * std::sin(a.azimuth),
          std::sin(a.elevation)};
}

render::Light keyLight(const glm::vec3 &up, const glm::vec3 &eyeDirection, const glm::vec3 &centre, float radius) {
  render::Light light;
  const glm::vec3 side = glm::normalize(glm::cross(glm::vec3(0, 0, 1), eyeDirection) + glm::vec3(1e-6f, 0, 0));
  // Upper left, slightly in front of the subject: a classic key light.
  light.towardLight = glm::normalize(up * 1.0f + eyeDirection * 0.35f - side * 0.5f);
  light.shadowCenter = centre;
  light.shadowRadius = radius;
  return light;
}

render::View orbitView(int x, int y, int w, int h, const glm::vec3 &target, double distance, const OrbitAngles &a,
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

Lens windowLens(const NdcWindow &window, double fovDeg, double aspect) {
  const double tanV = std::tan(0.5 * fovDeg * kDeg), tanH = tanV * aspect;
  const double windowTanV = 0.5 * (window.y1 - window.y0) * tanV, windowTanH = 0.5 * (window.x1 - window.x0) * tanH;
  return {2.0 * std::atan(windowTanV) / kDeg, windowTanH / windowTanV};
}

bool isWholeView(const NdcWindow &w) { return w.x0 == -1.0 && w.x1 == 1.0 && w.y0 == -1.0 && w.y1 == 1.0; }

glm::mat4 offAxisProjection(const NdcWindow &window, double fovDeg, double aspect, float nearPlane, float farPlane) {
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
std::pair<Vec3, double> fitPoints(const std::vector<Vec3> &points, double padAll, const OrbitAngles &a, double fovDeg,
                                  double aspect, const std::vector<double> &pads) {
  const Vec3 toEye(std::cos(a.elevation) * std::cos(a.azimuth), std::cos(a.elevation) * std::sin(a.azimuth),
                   std::sin(a.elevation));
  const Vec3 right = Vec3::UnitZ().cross(toEye).normalized();
  const Vec3 up = toEye.cross(right);
  Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
  for (const Vec3 &p : points) {
    const Vec3 c(p.dot(right), p.dot(up), p.dot(toEye));
    lo = lo.cwiseMin(c);
    hi = hi.cwiseMax(c);
  }
  const Vec3 mid = 0.5 * (lo + hi);
  Vec3 target = mid.x() * right + mid.y() * up + mid.z() * toEye;
  const double tanV = std::tan(0.5 * fovDeg * kDeg), tanH = tanV * aspect;
  double distance = 0.0;
  // Each point's offset from the target in the camera's axes, found once an
  // iteration and read by both of its passes (the sums are the same ones, in
  // the same order, either way).
  struct Offset {
    double right, up, toEye, pad;
  };
  std::vector<Offset> offsets(points.size());
  // Perspective makes near points take more room: re-centre on the projected
  // extent a few times (converges quickly; deterministic).
  for (int iteration = 0; iteration < 4; ++iteration) {
    distance = 0.0;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const Vec3 d = points[i] - target;
      Offset &o = offsets[i];
      o = {d.dot(right), d.dot(up), d.dot(toEye), pads.empty() ? padAll : pads[i]};
      const double depth = o.toEye + o.pad;
      distance =
          std::max({distance, depth + (std::abs(o.right) + o.pad) / tanH, depth + (std::abs(o.up) + o.pad) / tanV});
    }
    double xLo = 1e300, xHi = -1e300, yLo = 1e300, yHi = -1e300;
    for (const Offset &o : offsets) {
      const double w = distance - o.toEye;
      xLo = std::min(xLo, (o.right - o.pad) / w);
      xHi = std::max(xHi, (o.right + o.pad) / w);
      yLo = std::min(yLo, (o.up - o.pad) / w);
      yHi = std::max(yHi, (o.up + o.pad) / w);
    }
    target += distance * (0.5 * (xLo + xHi) * right + 0.5 * (yLo + yHi) * up);
  }
  return {target, distance * 1.03};
}

OrbitAngles orbitAngles(const scene::SceneSpec &spec, const model::RollingModel &model) {
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

double turnDeg(const OrbitAngles &a, const OrbitAngles &b) {
  return std::acos(std::clamp(towardEye(a).dot(towardEye(b)), -1.0, 1.0)) / kDeg;
}

OrbitAngles CameraFraming::along(const std::vector<Keyframe> &keys, double s) {
  if (s <= keys.front().s) return keys.front().angles;
  if (s >= keys.back().s) return keys.back().angles;
  std::size_t i = 0;
  while (i + 2 < keys.size() && s > keys[i + 1].s) ++i;
  // Between two places, the view direction turns the short way (its unit
  // vectors mixed, then normalised): no spin about the vertical.
  const double t = (s - keys[i].s) / std::max(keys[i + 1].s - keys[i].s, 1e-12);
  const Vec3 d = ((1.0 - t) * towardEye(keys[i].angles) + t * towardEye(keys[i + 1].angles)).normalized();
  const double azimuth = std::hypot(d.x(), d.y()) > 1e-9 ? std::atan2(d.y(), d.x()) : keys[i].angles.azimuth;
  // The azimuth stays near the keys' own (no 2π jump).
  const double near = keys[i].angles.azimuth;
  return {near + std::remainder(azimuth - near, 2.0 * std::numbers::pi), std::asin(std::clamp(d.z(), -1.0, 1.0))};
}

// A segment's camera keys laid over the shot it starts from.
void CameraFraming::layCameraKeys(const scene::CameraSpec &c, Shot &shot) {
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
}

// The camera [render] gives, at the scene's angles.
CameraFraming::Shot CameraFraming::sceneShot(const scene::SceneSpec &spec, const OrbitAngles &angles) {
  Shot shot{.azimuth = angles.azimuth,
            .elevation = angles.elevation,
            .fovDeg = spec.render.fovDeg,
            .distance = spec.render.distance,
            .follow = spec.render.follow};
  if (spec.render.target)
    shot.target = Vec3((*spec.render.target)[0], (*spec.render.target)[1], (*spec.render.target)[2]);
  return shot;
}

CameraFraming::CameraFraming(const scene::SceneSpec &spec, const model::RollingModel &model, FrameExtent extent,
                             bool forStill)
    : spec_(spec), model_(model), extent_(std::move(extent)) {
  const OrbitAngles sceneAngles = orbitAngles(spec, model);
  bool azimuthGiven = spec.locations.contains("render.azimuth_deg");
  bool elevationGiven = spec.locations.contains("render.elevation_deg");
  Shot shot = sceneShot(spec, sceneAngles);
  auto freeCamera = [](const Shot &sh) { return !sh.follow && !(sh.target && sh.distance); };
  if (spec.segments.empty()) {
    if (freeCamera(shot)) {
      const motion::FrameClock clock(model.path->length(), spec);
      const double seconds = double(clock.motionFrames()) / clock.fps().value();
      const Unhidden u =
          unhiddenAngles(sceneAngles, 0.0, model.path->length(), !azimuthGiven, !elevationGiven, true, 360.0, seconds);
      shot.azimuth = u.angles.azimuth;
      shot.elevation = u.angles.elevation;
      shot.orbits = u.orbits;
      shot.orbitOffset = u.orbitOffset;
      shot.cutsAway = u.cutAway;
    }
    shot.keyed = !freeCamera(shot) || azimuthGiven || elevationGiven;
    shots_.push_back(shot);
  }
  // A storyboard: each segment's keys laid over the previous segment's
  // camera; where the scene leaves the angles free, each segment gets the
  // view that keeps its own stretch of path in sight, turned from the
  // previous segment's view by at most kMaxFreeMoveDeg where one such does
  // (so that the one-second move between them stays as gentle as the
  // scene-given ones), and orbiting with the ball where no still view does.
  const std::vector<double> segmentSeconds = motion::FrameClock::segmentSeconds(model.segments, spec);
  for (std::size_t k = 0; k < spec.segments.size(); ++k) {
    const scene::CameraSpec &c = spec.segments[k].camera;
    // Where the previous segment's camera left off: the next one starts there.
    OrbitAngles previous{shot.azimuth, shot.elevation};
    if (shot.orbits && k > 0) {
      const Vec3 p = model.path->at(model.segments[k].start).point;
      previous.azimuth = std::atan2(p.y(), p.x()) + shot.orbitOffset;
    }
    shot.azimuth = previous.azimuth;
    shot.elevation = previous.elevation;
    if (!shot.keys.empty() && k > 0) previous = along(shot.keys, model.segments[k].start);
    shot.azimuth = previous.azimuth;
    shot.elevation = previous.elevation;
    shot.orbits = false;
    shot.orbitOffset = 0.0;
    shot.keys.clear();
    shot.cutsAway = false;
    layCameraKeys(c, shot);
    azimuthGiven = azimuthGiven || c.azimuthDeg.has_value();
    elevationGiven = elevationGiven || c.elevationDeg.has_value();
    shot.moveSeconds = kCameraMove;
    if (!(shot.target && shot.distance)) {  // follow: the angles are still free
      model::SegmentSpan span = model.segments[k];
      double seconds = segmentSeconds[k];
      // A hold looks ahead: its camera moves (while the ball rests) to the
      // view the next motion wants, where that segment adds no keys.
      if (span.end == span.start && k + 1 < spec.segments.size()) {
        const scene::CameraSpec &next = spec.segments[k + 1].camera;
        if (!next.azimuthDeg && !next.elevationDeg && !next.follow && !next.target && !next.distance && !next.fovDeg) {
          span = model.segments[k + 1];
          seconds = segmentSeconds[k + 1];
        }
      }
      // (A closing hold keeps the stretch of the shot before it: the ball
      // rests where that one framed it.)
      if (span.end > span.start) {
        shot.ownStretch = !forStill && spec.segments.size() > 1 && !shot.follow && !shot.target;
        shot.stretchStart = span.start;
        shot.stretchEnd = span.end;
      }
      const OrbitAngles base{shot.azimuth, shot.elevation};
      Unhidden u = unhiddenAngles(base, span.start, span.end, !azimuthGiven, !elevationGiven, true,
                                  k == 0 ? 360.0 : kMaxFreeMoveDeg, seconds, false, shot.follow);
      if (k > 0 && u.share < 0.9)
        u = unhiddenAngles(base, span.start, span.end, !azimuthGiven, !elevationGiven, true, 360.0, seconds, false,
                           shot.follow);
      shot.azimuth = u.angles.azimuth;
      shot.elevation = u.angles.elevation;
      shot.orbits = u.orbits;
      shot.orbitOffset = u.orbitOffset;
      shot.keys = u.keys;
      shot.cutsAway = u.cutAway;
      // A turn larger than kMaxFreeMoveDeg takes longer than a second, where
      // rollspin chose the view; a move to angles the scene gives takes the
      // documented second.
      if (k > 0 && !(azimuthGiven && elevationGiven))
        shot.moveSeconds = std::max(kCameraMove, turnDeg(previous, u.angles) / kMaxFreeMoveDeg);
      // A camera that turns with s from where the previous one left off
      // needs no move.
      if (k > 0 && !u.keys.empty() && turnDeg(previous, u.keys.front().angles) < 1e-6) shot.moveSeconds = 0.0;
    }
    shot.keyed = (shot.target && shot.distance) || azimuthGiven || elevationGiven;
    shots_.push_back(shot);
  }
  holdTheMovesAhead(segmentSeconds);
  findHiddenSpans();
}

bool CameraFraming::mayCloseIn() const {
  return std::any_of(shots_.begin(), shots_.end(), [](const Shot &s) { return s.ownStretch; });
}

bool CameraFraming::fixedByScene() const {
  return std::all_of(shots_.begin(), shots_.end(), [](const Shot &s) { return s.target && s.distance; });
}

bool CameraFraming::orbits() const {
  return std::any_of(shots_.begin(), shots_.end(), [](const Shot &s) { return s.orbits; });
}

bool CameraFraming::moving(const StoryPlace &story) const {
  const std::size_t k = std::min(story.segment, shots_.size() - 1);
  return k > 0 && story.seconds < std::min(shots_[k].moveSeconds, story.duration);
}

bool CameraFraming::follows(const StoryPlace &story) const {
  return shots_[std::min(story.segment, shots_.size() - 1)].follow;
}

bool CameraFraming::cutsAway(const StoryPlace &story) const {
  const std::size_t k = std::min(story.segment, shots_.size() - 1);
  return shots_[k].cutsAway || (moving(story) && shots_[k - 1].cutsAway);
}

std::vector<std::string> CameraFraming::hiddenWarnings() const { return hiddenWarnings_; }

// Where the scene's own keys fix the camera, check it against the sight
// lines at the clip's frames (every frame, or about 600 spread over a long
// clip) and name the seconds it hides the ball in.
void CameraFraming::findHiddenSpans() {
  if (!extent_.surface) return;
  if (model_.surface && model_.surface->look().cutAwayTowardEye) return;  // cut open towards the eye
  const motion::FrameClock clock = motion::clipClock(spec_, model_);
  const long long frames = clock.frameCount();
  const long long step = std::max<long long>(1, frames / 600);
  const double fps = clock.fps().value();
  const int w = int(spec_.render.width), h = int(spec_.render.height);
  const double R = model_.ballRadius;
  struct Span {
    double from = -1.0, to = -1.0;
  };
  std::vector<Span> spans(shots_.size());
  for (long long frame = 0; frame < frames; frame += step) {
    const StoryPlace story = clock.place(frame);
    if (cutsAway(story)) continue;  // the surface opens where it hides the ball
    const double s = clock.arcLength(frame);
    const Aim aim = aimAt(story, w, h, s);
    const Vec3 eye = aim.target + aim.distance * towardEye({aim.azimuth, aim.elevation});
    if (extent_.surface->visibleShare(eye, model_.path->at(s).centre(R), R) >= 0.9) continue;
    Span &span = spans[std::min(story.segment, spans.size() - 1)];
    const double t = double(frame) / fps;
    if (span.from < 0.0) span.from = t;
    span.to = t + double(step) / fps;
  }
  for (std::size_t k = 0; k < spans.size(); ++k) {
    if (spans[k].from < 0.0) continue;
    const std::string who = spec_.segments.empty() ? std::string("the scene") : scene::SceneSpec::segmentKey(k);
    hiddenWarnings_.push_back(
        fmt::format("warning: {}: the camera hides the ball behind the surface (under 90 % "
                    "of it seen) from {:.2f} s to {:.2f} s "
                    "of the clip; {}",
                    who, spans[k].from, spans[k].to,
                    shots_[k].keyed ? "the scene's own camera keys fix this view (leave "
                                      "azimuth_deg / elevation_deg, target and "
                                      "follow out to let rollspin choose one)"
                                    : "no view rollspin tried keeps it in sight (set the "
                                      "camera keys of this segment)"));
  }
}

CameraFraming::Aim CameraFraming::aimOf(const Shot &shot, int w, int h, double s) const {
  OrbitAngles a{shot.azimuth, shot.elevation};
  if (shot.orbits) {  // with the ball round the z axis (see the constructor)
    const Vec3 p = model_.path->at(s).point;
    a.azimuth = std::atan2(p.y(), p.x()) + shot.orbitOffset;
  }
  if (!shot.keys.empty()) a = along(shot.keys, s);
  const double R = model_.ballRadius;
  // Fit into the window: a narrower field of view about its centre (the
  // projection is shifted off axis to put that centre there, ballCamera).
  const Lens lens = windowLens(window_, shot.fovDeg, double(w) / double(std::max(h, 1)));
  const double fovDeg = lens.fovDeg, aspect = lens.aspect;
  // A camera that follows, or one whose target and distance the scene
  // gives, uses nothing of the fit.
  Vec3 target = Vec3::Zero();
  double distance = 0.0;
  if (!shot.follow && !(shot.target && shot.distance)) {
    std::tie(target, distance) = framedFit(a, fovDeg, aspect, !shot.target);
    if (closeIn_ > 0.0 && shot.ownStretch && !shot.distance)
      closeInOnStretch(shot, a, fovDeg, aspect, target, distance);
  }
  if (shot.follow) {
    target = model_.path->at(s).centre(R);
    distance = fitDistance(4.0 * R, fovDeg, aspect);
  }
  if (shot.target) target = *shot.target;
  if (shot.distance) distance = *shot.distance;
  return {target, distance, a.azimuth, a.elevation, shot.fovDeg};
}

std::pair<Vec3, double> CameraFraming::framedFit(const OrbitAngles &a, double fovDeg, double aspect, bool held) const {
  const FitKey key{std::bit_cast<std::uint64_t>(a.azimuth),
                   std::bit_cast<std::uint64_t>(a.elevation),
                   std::bit_cast<std::uint64_t>(fovDeg),
                   std::bit_cast<std::uint64_t>(aspect),
                   std::bit_cast<std::uint64_t>(window_.x0),
                   std::bit_cast<std::uint64_t>(window_.x1),
                   std::bit_cast<std::uint64_t>(window_.y0),
                   std::bit_cast<std::uint64_t>(window_.y1),
                   (std::uint64_t(innerEdges_.left) << 0) | (std::uint64_t(innerEdges_.right) << 1) |
                       (std::uint64_t(innerEdges_.bottom) << 2) | (std::uint64_t(innerEdges_.top) << 3) |
                       (std::uint64_t(held) << 4)};
  const std::lock_guard<std::mutex> lock(fitsMutex_);
  if (const auto it = fits_.find(key); it != fits_.end()) return it->second;
  auto [target, distance] = fitPoints(extent_.points, model_.ballRadius, a, fovDeg, aspect, extent_.pads);
  if (held) {
    holdOutline(target, distance, a, fovDeg, aspect);
    keepOffViewEdges(target, distance, a, fovDeg, aspect);
  }
  if (fits_.size() >= kMaxFits) fits_.clear();
  fits_.emplace(key, std::pair{target, distance});
  return {target, distance};
}


// In the window's own NDC the subject's points (padded by R) must stay in
// [-1, 1]; the view's edge lies at (±1 − centre) / half-width of the
// window. The shift is continuous in the angles (maxima over points), so a
// turning camera pans smoothly.
void CameraFraming::holdOutline(Vec3 &target, double &distance, const OrbitAngles &a, double fovDeg,
                                double aspect) const {
  if (extent_.outline.empty()) return;
  const double R = model_.ballRadius;
  const ScreenAxes screen = screenAxes(a, fovDeg, aspect);
  const Vec3 &toEye = screen.toEye;
  const Vec3(&axes)[2] = screen.axes;
  const double(&tans)[2] = screen.tans;
  const double centres[2] = {0.5 * (window_.x0 + window_.x1), 0.5 * (window_.y0 + window_.y1)};
  const double halves[2] = {0.5 * (window_.x1 - window_.x0), 0.5 * (window_.y1 - window_.y0)};
  const bool lowInner[2] = {innerEdges_.left, innerEdges_.bottom}, highInner[2] = {innerEdges_.right, innerEdges_.top};
  for (int axis = 0; axis < 2; ++axis) {
    if (lowInner[axis] == highInner[axis]) continue;  // none, or both sides: panning cannot help
    for (int pass = 0; pass < 2; ++pass) {
      auto ndc = [&](const Vec3 &p, double pad) {
        const Vec3 d = p - target;
        const double w = std::max(distance - d.dot(toEye), 1e-9);
        return std::pair{(d.dot(axes[axis]) - pad) / (w * tans[axis]), (d.dot(axes[axis]) + pad) / (w * tans[axis])};
      };
      double subjectLo = 1e300, subjectHi = -1e300, outlineLo = 1e300, outlineHi = -1e300;
      for (std::size_t i = 0; i < extent_.points.size(); ++i) {
        const auto [lo, hi] = ndc(extent_.points[i], extent_.padOf(i, R));
        subjectLo = std::min(subjectLo, lo);
        subjectHi = std::max(subjectHi, hi);
      }
      for (const Vec3 &p : extent_.outline) {
        const auto [lo, hi] = ndc(p, 0.0);
        outlineLo = std::min(outlineLo, lo);
        outlineHi = std::max(outlineHi, hi);
      }
      // The inner edge and how far the outline reaches, both measured away
      // from the window's centre towards that edge.
      // (A margin of 3 % of the window: the outline is sampled, and a
      // surface that just touches the seam reads as cut.)
      const double edge =
          (highInner[axis] ? (1.0 - centres[axis]) / halves[axis] : (1.0 + centres[axis]) / halves[axis]) - 0.03;
      const double reach = highInner[axis] ? outlineHi : -outlineLo;
      if (pass == 0) {
        // Pan the picture away from the edge, as far as the subject keeps
        // inside the window on the other side.
        // (Short of the view's edge by kEdgeMargin: keepOffViewEdges.)
        const double keep = kEdgeMargin / halves[axis];
        const double room = std::max(0.0, highInner[axis] ? subjectLo + 1.0 - keep : 1.0 - keep - subjectHi);
        const double shift = std::clamp(reach - edge, 0.0, room) * (highInner[axis] ? -1.0 : 1.0);
        target -= shift * distance * tans[axis] * axes[axis];
      } else if (reach > edge && edge > 0.0) {
        // Still cut: step back, by up to kOutlineStepBack (the reach over
        // the edge shrinks with the distance).
        distance *= std::min(reach / edge, kOutlineStepBack);
      }
    }
  }
}

// In the window's NDC a padded point's reach scales with 1/w, w its depth
// from the eye: stepping back from `distance` to k · distance shrinks it
// by about w / (w + (k − 1) distance). One step with the largest ratio
// needed, then a second for what that approximation leaves; continuous in
// the angles (maxima over points), so a turning camera stays smooth.
void CameraFraming::keepOffViewEdges(const Vec3 &target, double &distance, const OrbitAngles &a, double fovDeg,
                                     double aspect) const {
  const double R = model_.ballRadius;
  const ScreenAxes screen = screenAxes(a, fovDeg, aspect);
  const Vec3 &toEye = screen.toEye;
  const Vec3(&axes)[2] = screen.axes;
  const double(&tans)[2] = screen.tans;
  const double los[2] = {window_.x0, window_.y0}, his[2] = {window_.x1, window_.y1};
  for (int pass = 0; pass < 2; ++pass) {
    double factor = 1.0;
    for (int axis = 0; axis < 2; ++axis) {
      const double half = 0.5 * (his[axis] - los[axis]);
      if (half <= 0.0) continue;
      // The window NDC the subject may reach on each side: 1 where the
      // window's edge lies inside the view (text beyond it), else short of
      // the view's edge by kEdgeMargin.
      const double limitHi = his[axis] >= 1.0 - 1e-9 ? 1.0 - kEdgeMargin / half : 1.0;
      const double limitLo = los[axis] <= -1.0 + 1e-9 ? 1.0 - kEdgeMargin / half : 1.0;
      for (std::size_t i = 0; i < extent_.points.size(); ++i) {
        const Vec3 d = extent_.points[i] - target;
        const double w = std::max(distance - d.dot(toEye), 1e-9), pad = extent_.padOf(i, R);
        const double hi = (d.dot(axes[axis]) + pad) / (w * tans[axis]),
                     lo = -(d.dot(axes[axis]) - pad) / (w * tans[axis]);
        for (const auto &[reach, limit] : {std::pair{hi, limitHi}, std::pair{lo, limitLo}}) {
          if (reach <= limit || limit <= 0.0) continue;
          // reach · w / (w + (k − 1) distance) = limit
          factor = std::max(factor, 1.0 + (reach / limit - 1.0) * w / distance);
        }
      }
    }
    distance *= factor;
  }
}

CameraFraming::Aim CameraFraming::aimAt(const StoryPlace &story, int w, int h, double s) const {
  const std::size_t k = std::min(story.segment, shots_.size() - 1);
  const Aim to = aimOf(shots_[k], w, h, s);
  const double move = std::min(shots_[k].moveSeconds, story.duration);
  if (k == 0 || !(story.seconds < move)) return to;
  // On the way from the previous segment's camera where it left off (an
  // orbiting one no longer follows the ball): eased, the azimuth the short
  // way round. Equal cameras blend to themselves exactly.
  const Aim from = aimOf(shots_[k - 1], w, h, k < model_.segments.size() ? model_.segments[k].start : s);
  const double x = motion::ease(scene::Easing::Smooth, story.seconds / move);
  auto mix = [x](double a, double b) { return a + (b - a) * x; };
  // The view direction turns along the great circle between the two (at
  // an even rate: the turn is the move's angle, not the sum of an azimuth
  // and an elevation turn); straight up or down keeps the azimuth mixed.
  const Vec3 a = towardEye({from.azimuth, from.elevation}), b = towardEye({to.azimuth, to.elevation});
  const double angle = std::acos(std::clamp(a.dot(b), -1.0, 1.0));
  double azimuth = from.azimuth + std::remainder(to.azimuth - from.azimuth, 2.0 * std::numbers::pi) * x;
  double elevation = mix(from.elevation, to.elevation);
  if (angle > 1e-9 && angle < std::numbers::pi - 1e-6) {
    const Vec3 d = (std::sin((1.0 - x) * angle) * a + std::sin(x * angle) * b) / std::sin(angle);
    if (std::hypot(d.x(), d.y()) > 1e-9)
      azimuth = from.azimuth + std::remainder(std::atan2(d.y(), d.x()) - from.azimuth, 2.0 * std::numbers::pi);
    elevation = std::asin(std::clamp(d.z(), -1.0, 1.0));
  }
  Aim mixed{from.target + (to.target - from.target) * x, mix(from.distance, to.distance), azimuth, elevation,
            mix(from.fovDeg, to.fovDeg)};
  if (closeIn_ > 0.0 && (shots_[k].ownStretch || shots_[k - 1].ownStretch)) keepBallInView(mixed, from, to, x, w, h, s);
  return mixed;
}

render::View CameraFraming::ballCamera(int x, int y, int w, int h, double s, const StoryPlace &story) const {
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
