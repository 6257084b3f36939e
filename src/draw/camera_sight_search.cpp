// The occlusion-aware search of CameraFraming (camera_framing.hpp): the
// orbit angles near the scene's that keep the ball's disc in sight along a
// stretch of the path, by sight lines through the surface's mesh.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "draw/camera_framing.hpp"
#include "draw/draw_style.hpp"
#include "motion/frame_clock.hpp"

namespace rollspin::draw {

using geometry::Vec3;
using motion::StoryPlace;

namespace {

// The least share, over [s0, s1], of the ball's disc that the eye sees past
// the surface as drawn (or any share below `useless`, once it is clear the
// least is that low). eyeAt(s): the eye at arc length s.
template <typename EyeAt>
double leastVisibleShare(const model::RollingModel &model, const SightLines &surface, const EyeAt &eyeAt, double s0,
                         double s1, double useless = 0.0) {
  const double R = model.ballRadius;
  double least = 1.0;
  const int steps = s1 > s0 ? 48 : 0;
  for (int i = 0; i <= steps && least >= useless && least > 0.0; ++i) {
    const double s = steps == 0 ? s0 : s0 + (s1 - s0) * i / double(steps);
    least = std::min(least, surface.visibleShare(eyeAt(s), model.path->at(s).centre(R), R));
  }
  return least;
}

// The share of the contact path on [s0, s1] the eye sees (points lifted a
// little off the surface, so that the mesh's chords under them do not count).
template <typename EyeAt>
double visiblePathShare(const model::RollingModel &model, const SightLines &surface, const EyeAt &eyeAt, double s0,
                        double s1) {
  const double R = model.ballRadius;
  int seen = 0;
  for (int i = 0; i <= 96; ++i) {
    const double s = s0 + (s1 - s0) * i / 96.0;
    const geometry::DarbouxSample f = model.path->at(s);
    if (!surface.blocked(eyeAt(s), f.point + 0.05 * R * f.normal, 0.05 * R)) ++seen;
  }
  return seen / 97.0;
}

// Where a view puts the eye: a still camera that frames the extent from
// the orbit angles, or (follow) one that stands fitDistance(4R) from the
// ball at s.
struct SightEyes {
  const scene::SceneSpec &spec;
  const model::RollingModel &model;
  const FrameExtent &extent;
  double aspect;
  bool follow;
  double followDistance;

  [[nodiscard]] Vec3 still(const OrbitAngles &a) const {
    const auto [target, distance] =
        fitPoints(extent.points, model.ballRadius, a, spec.render.fovDeg, aspect, extent.pads);
    return Vec3(target + spec.render.distance.value_or(distance) * towardEye(a));
  }
  // The eye at s for the orbit angles a (`still`: the still eye for a).
  [[nodiscard]] Vec3 at(const OrbitAngles &a, double s, const Vec3 &still) const {
    return follow ? Vec3(model.path->at(s).centre(model.ballRadius) + followDistance * towardEye(a)) : still;
  }
};

// A still view tried, and what turning there from the given view costs.
struct StillCandidate {
  OrbitAngles angles;
  double cost;
};

// The still views round `base` in the order they are tried, cheapest first:
// each 30° of azimuth and 10° of elevation turned costs 1. (A storyboard's
// segment may also look from lower down, `mayLower`: round a torus's tube
// or down a sphere's meridian the ball passes under the rim a high view
// sees.) A view from below stays below.
std::vector<StillCandidate> stillViewsNear(const OrbitAngles &base, bool azimuthFree, bool elevationFree, bool mayLower,
                                           double maxTurnDeg) {
  std::vector<StillCandidate> candidates;
  const double below = base.elevation < 0.0 ? -1.0 : 1.0;
  for (const double turn : {0.0, 30.0, -30.0, 60.0, -60.0, 90.0, -90.0, 135.0, -135.0, 180.0}) {
    if (turn != 0.0 && !azimuthFree) break;
    for (const double degrees : {0.0, 35.0, 45.0, 55.0, 65.0, 75.0, -15.0, -5.0}) {
      if (degrees != 0.0 && !elevationFree) break;
      if (degrees < 0.0 && !mayLower) break;
      const double elevation = degrees < 0.0 ? below * std::min(below * base.elevation, -degrees * kDeg)
                                             : below * std::max(below * base.elevation, degrees * kDeg);
      if (degrees != 0.0 && elevation == base.elevation) continue;
      const OrbitAngles angles{base.azimuth + turn * kDeg, elevation};
      if (turnDeg(angles, base) > maxTurnDeg) continue;
      candidates.push_back({angles, std::abs(turn) / 30.0 + std::abs(elevation - base.elevation) / kDeg / 10.0});
    }
  }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const StillCandidate &x, const StillCandidate &y) { return x.cost < y.cost; });
  return candidates;
}

// A view that orbits with the ball's longitude about the z axis, offset
// from it by `offset`, at `elevation`; share < 0: none.
struct LongitudeOrbit {
  double elevation = 0.0, offset = 0.0, share = -1.0;
};

// The ball's longitude about the z axis at s.
double ballLongitude(const model::RollingModel &model, double s) {
  const Vec3 p = model.path->at(s).point;
  return std::atan2(p.y(), p.x());
}

// The orbiting view that sees most of the ball (the first that sees
// ≥ 96 %). An orbit only makes sense where the path keeps away from the
// axis (else the view would spin) and the ball goes round slowly enough:
// the view turns by the longitude's rate times cos(elevation), at most
// kMaxTurnRateDeg a second.
LongitudeOrbit orbitWithLongitude(const SightEyes &eyes, const OrbitAngles &base, double s0, double s1,
                                  bool elevationFree, double maxTurnDeg, double seconds, double maxTurnRateDeg) {
  const model::RollingModel &model = eyes.model;
  const double R = model.ballRadius;
  bool offAxis = true;
  double longitudeRate = 0.0;  // the fastest, degrees a second
  for (int i = 0; i <= 48 && offAxis; ++i) {
    const double sa = s0 + (s1 - s0) * motion::ease(eyes.spec.animation.easing, i / 48.0);
    const Vec3 p = model.path->at(sa).point;
    offAxis = std::hypot(p.x(), p.y()) > 0.5 * R;
    if (i > 0) {
      const double sb = s0 + (s1 - s0) * motion::ease(eyes.spec.animation.easing, (i - 1) / 48.0);
      const double turn =
          std::abs(std::remainder(ballLongitude(model, sa) - ballLongitude(model, sb), 2.0 * std::numbers::pi)) / kDeg;
      longitudeRate = std::max(longitudeRate, turn / (seconds / 48.0));
    }
  }
  LongitudeOrbit orbit;
  if (!offAxis) return orbit;
  const double below = base.elevation < 0.0 ? -1.0 : 1.0;
  const double offset = base.azimuth - ballLongitude(model, s0);
  for (const double degrees : {0.0, 35.0, 45.0, 55.0, 65.0, 75.0}) {
    if (degrees != 0.0 && !elevationFree) break;
    const double elevation = below * std::max(below * base.elevation, degrees * kDeg);
    if (turnDeg({base.azimuth, elevation}, base) > maxTurnDeg) continue;
    if (longitudeRate * std::cos(elevation) > maxTurnRateDeg) continue;
    auto eyeAt = [&](double s) {
      const OrbitAngles a{ballLongitude(model, s) + offset, elevation};
      return eyes.follow ? eyes.at(a, s, Vec3::Zero()) : eyes.still(a);
    };
    const double share = leastVisibleShare(model, *eyes.extent.surface, eyeAt, s0, s1);
    if (share > orbit.share + 1e-9) orbit = {elevation, offset, share};
    if (share >= 0.96) break;
  }
  return orbit;
}

// A camera that turns with s: the view direction at each place.
struct TurningPath {
  std::vector<double> s;
  std::vector<OrbitAngles> angles;
  double share = 0.0;  // the share of the ball each direction sees
};

// The view directions a turning camera chooses from: `base` first, then a
// grid of kAzimuthStep by kElevationStep.
constexpr double kAzimuthStep = 10.0, kElevationStep = 7.5;
std::vector<OrbitAngles> turningDirections(const OrbitAngles &base) {
  std::vector<OrbitAngles> directions{base};
  const int azimuths = int(std::lround(360.0 / kAzimuthStep));
  for (int a = 0; a < azimuths; ++a)
    for (double degrees = -75.0; degrees <= 75.0 + 1e-9; degrees += kElevationStep)
      directions.push_back({base.azimuth + std::remainder(a * kAzimuthStep, 360.0) * kDeg, degrees * kDeg});
  return directions;
}

// The cheapest way through the places (dynamic programming): at place i
// only directions that see the ball there and on the way from place i − 1
// (seen[i − 1] and seen[i]: the camera passes between the two directions),
// a step from one place to the next only to a `near` direction, costing the
// squared turn between the two; the first costs its squared turn from
// `base`, or (anchored) must be the grid's first, `base` itself. The
// directions' indices, one per place; empty where none sees it through.
std::vector<std::size_t> cheapestTurns(const std::vector<std::vector<char>> &seen,
                                       const std::vector<std::vector<std::size_t>> &near,
                                       const std::vector<OrbitAngles> &directions, const OrbitAngles &base,
                                       bool anchored) {
  const std::size_t places = seen.size(), n = directions.size();
  std::vector<std::vector<double>> cost(places, std::vector<double>(n, 1e300));
  std::vector<std::vector<std::size_t>> from(places, std::vector<std::size_t>(n, 0));
  for (std::size_t j = 0; j < n; ++j)
    if (seen[0][j] && (!anchored || j == 0)) cost[0][j] = std::pow(turnDeg(base, directions[j]), 2);
  for (std::size_t i = 1; i < places; ++i)
    for (std::size_t j = 0; j < n; ++j) {
      if (!seen[i][j] || !seen[i - 1][j]) continue;
      for (const std::size_t k : near[j]) {
        const double c = cost[i - 1][k] + std::pow(turnDeg(directions[k], directions[j]), 2);
        if (c < cost[i][j]) {
          cost[i][j] = c;
          from[i][j] = k;
        }
      }
    }
  const std::vector<double> &lastCost = cost.back();
  const std::size_t last = std::size_t(std::min_element(lastCost.begin(), lastCost.end()) - lastCost.begin());
  if (lastCost[last] >= 1e299) return {};
  std::vector<std::size_t> chosen(places);
  for (std::size_t j = last, i = places; i-- > 0;) {
    chosen[i] = j;
    j = from[i][j];
  }
  return chosen;
}

// A camera that turns as the ball goes (round a torus's tube no still view
// sees it all): view directions at places evenly spread in time over the
// motion's `seconds` (its easing undone), on the grid of
// turningDirections, each seeing the ball there and a third and two thirds
// of the way to the next place (the camera turns between two places'
// directions there), turned from one place to the next by at most
// maxFreeMoveDeg a second, chosen for the least sum of squared turns from
// the given view and between places (cheapestTurns); first seeing ≥ 99 %,
// else ≥ 95 %. None where no such camera sees it.
std::optional<TurningPath> turningWithBall(const SightEyes &eyes, const OrbitAngles &base, double s0, double s1,
                                           double seconds, bool anchored, double maxFreeMoveDeg) {
  const model::RollingModel &model = eyes.model;
  const double R = model.ballRadius;
  // A step of the grid (its diagonal at the horizon) must fit the turn a
  // place-to-place time allows: places at least this far apart in time.
  const double minStepSeconds = std::hypot(kAzimuthStep, kElevationStep) / maxFreeMoveDeg;
  const int intervals = std::clamp(int(std::floor(seconds / minStepSeconds)), 1, 40);
  const double maxStepDeg = maxFreeMoveDeg * seconds / intervals;
  const int places = intervals + 1;
  const std::vector<OrbitAngles> directions = turningDirections(base);
  const std::size_t n = directions.size();
  std::vector<Vec3> stillEyes, toward;
  for (const OrbitAngles &d : directions) {
    stillEyes.push_back(eyes.still(d));
    toward.push_back(towardEye(d));
  }
  // Each direction's neighbours within one step's turn.
  const double maxStepCos = std::cos(maxStepDeg * kDeg);
  std::vector<std::vector<std::size_t>> near(n);
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t k = 0; k < n; ++k)
      if (toward[j].dot(toward[k]) >= maxStepCos - 1e-12) near[j].push_back(k);
  const scene::Easing easing = eyes.spec.animation.easing;
  auto placeS = [&](double i) { return s0 + (s1 - s0) * motion::ease(easing, i / intervals); };
  for (const double enough : {0.99, 0.95}) {
    // seen[i][j]: direction j sees the ball at place i and on the way to
    // place i + 1 (a third and two thirds of the time there).
    std::vector<std::vector<char>> seen(std::size_t(places), std::vector<char>(n, 0));
    for (int i = 0; i < places; ++i)
      for (std::size_t j = 0; j < n; ++j) {
        bool all = true;
        for (const double part : {0.0, 1.0 / 3.0, 2.0 / 3.0}) {
          if (i == intervals && part > 0.0) break;
          const double s = placeS(i + part);
          if (eyes.extent.surface->visibleShare(eyes.at(directions[j], s, stillEyes[j]), model.path->at(s).centre(R),
                                                R) < enough) {
            all = false;
            break;
          }
        }
        seen[std::size_t(i)][j] = all;
      }
    const std::vector<std::size_t> chosen = cheapestTurns(seen, near, directions, base, anchored);
    if (chosen.empty()) continue;
    TurningPath path;
    path.share = enough;
    for (std::size_t i = 0; i < chosen.size(); ++i) {
      path.s.push_back(placeS(double(i)));
      path.angles.push_back(directions[chosen[i]]);
    }
    return path;
  }
  return std::nullopt;
}

}  // namespace

// The default camera keeps the ball in sight: where the scene leaves the
// orbit angles free, try views round the given one (each step of turn
// costs) and, among those that see ≥ 96 % of the ball's disc at every place
// on [s0, s1] (else ≥ 90 %), keep the one that sees most of the contact
// path less 5 % per step; the given view when it sees ≥ 96 %. Where no
// still view does (a path round the back of a sphere or a cylinder), one
// that orbits with the ball's longitude, starting from the given azimuth.
// An inside sphere is cut open towards the eye (BallView), so its view
// already sees in.
CameraFraming::Unhidden CameraFraming::unhiddenAngles(OrbitAngles base, double s0, double s1, bool azimuthFree,
                                                      bool elevationFree, bool mayOrbit, double maxTurnDeg,
                                                      double seconds, bool mayLower, bool follow) const {
  Unhidden out{.angles = base};
  const bool cutOpen = model_.surface && model_.surface->look().cutAwayTowardEye;
  if (!extent_.surface || cutOpen || !(azimuthFree || elevationFree)) return out;
  const double aspect = double(spec_.render.width) / double(std::max<long long>(spec_.render.height, 1));
  const double R = model_.ballRadius;
  const SightEyes eyes{spec_, model_, extent_, aspect, follow, fitDistance(4.0 * R, spec_.render.fovDeg, aspect)};
  const std::vector<StillCandidate> candidates = stillViewsNear(base, azimuthFree, elevationFree, mayLower, maxTurnDeg);
  // The share is sampled (25 rays, 49 places) for a full-view lens; the
  // text layout narrows the lens later and moves the eye a little, so a view
  // that sees ≥ 96 % is preferred to one that only just sees 90 %.
  struct Seen {
    const StillCandidate *candidate;
    double share, score;
  };
  std::vector<Seen> seen;
  const StillCandidate *leastHidden = nullptr;
  double bestShare = -1.0;
  for (const StillCandidate &c : candidates) {
    const Vec3 eye = eyes.still(c.angles);
    auto eyeAt = [&](double s) { return eyes.at(c.angles, s, eye); };
    const double share = leastVisibleShare(model_, *extent_.surface, eyeAt, s0, s1, std::min(0.9, bestShare));
    if (share > bestShare + 1e-9) {
      bestShare = share;
      leastHidden = &c;
    }
    if (share >= 0.9)
      seen.push_back({&c, share, visiblePathShare(model_, *extent_.surface, eyeAt, s0, s1) - 0.05 * c.cost});
    if (share >= 0.96 && c.cost == 0.0) break;  // the given view sees it all
  }
  out.share = bestShare;
  auto pickStill = [&](double enough) {
    const Seen *chosen = nullptr;
    for (const Seen &v : seen)
      if (v.share >= enough && (chosen == nullptr || v.score > chosen->score + 1e-9)) chosen = &v;
    if (chosen) {
      out.angles = chosen->candidate->angles;
      out.share = chosen->share;
    }
    return chosen != nullptr;
  };
  if (pickStill(0.96)) return out;

  // An orbit that sees ≥ 96 % is preferred to a still view that sees 90 %.
  Unhidden orbit{.angles = base, .share = -1.0};
  if (azimuthFree && mayOrbit && s1 > s0) {
    const LongitudeOrbit o =
        orbitWithLongitude(eyes, base, s0, s1, elevationFree, maxTurnDeg, seconds, kMaxTurnRateDeg);
    if (o.share > -1.0)
      orbit = {.angles = {base.azimuth, o.elevation}, .orbits = true, .orbitOffset = o.offset, .share = o.share};
  }
  if (orbit.share >= 0.96) return orbit;
  if (pickStill(0.9)) return out;
  if (orbit.share >= 0.9) return orbit;
  // Last, a camera that turns as the ball goes. Within a gentle turn of the
  // previous segment's view (maxTurnDeg under 360°), it starts from that
  // view itself.
  const bool anchored = maxTurnDeg < 360.0;
  if (mayOrbit && azimuthFree && elevationFree && s1 > s0) {
    if (const std::optional<TurningPath> path =
            turningWithBall(eyes, base, s0, s1, seconds, anchored, kMaxFreeMoveDeg)) {
      std::vector<Keyframe> keys(path->s.size());
      for (std::size_t i = 0; i < keys.size(); ++i) keys[i] = {path->s[i], path->angles[i]};
      out = {.angles = keys.front().angles, .share = path->share};
      out.keys = std::move(keys);
      return out;
    }
  }
  // No view keeps the ball in sight past the surface (round a torus's tube
  // the inner side is hidden from every view outside the hole that a gentle
  // turn reaches): the calmest one, the still view that hides it least, and
  // the surface cut away towards the eye where it hides the ball (BallView).
  if (leastHidden) out.angles = leastHidden->angles;
  out.cutAway = true;
  return out;
}

}  // namespace rollspin::draw
