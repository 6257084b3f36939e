// CameraFraming's close-in (issue 54, paper cut 8): a storyboard segment
// whose whole-clip framing leaves the ball under a tenth of its view comes
// closer towards its own stretch of path, as far as the text beside it and
// the window allow; and the moves between such shots keep the ball in view.
#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>
#include <vector>

#include "draw/camera_framing.hpp"
#include "draw/draw_style.hpp"
#include "draw/screen_axes.hpp"

namespace rollspin::draw {

using geometry::Vec3;

// While the camera moves into the next motion's shot, the ball is already
// on that motion's path: a shot framed for its own stretch keeps it in view
// too (the arc length of the move's seconds, taken as uniform), so that the
// eased move between two views that both hold it holds it.
void CameraFraming::holdTheMovesAhead(const std::vector<double> &segmentSeconds) {
  // A camera that turns on from where the previous one left off needs no
  // move, unless either frames its own stretch: then they differ in
  // distance and target, and the move blends them.
  for (std::size_t k = 1; k < shots_.size(); ++k)
    if (shots_[k].moveSeconds == 0.0 && (shots_[k].ownStretch || shots_[k - 1].ownStretch))
      shots_[k].moveSeconds = kCameraMove;
  for (std::size_t k = 0; k + 1 < shots_.size() && k + 1 < model_.segments.size(); ++k) {
    const model::SegmentSpan &next = model_.segments[k + 1];
    if (!shots_[k].ownStretch || next.end <= next.start || segmentSeconds[k + 1] <= 0.0) continue;
    const double moved = std::min(1.0, shots_[k + 1].moveSeconds / segmentSeconds[k + 1]);
    shots_[k].stretchEnd = std::max(shots_[k].stretchEnd, next.start + moved * (next.end - next.start));
  }
}

// Two views framed close to their own stretches each hold the ball where
// the move between them starts and ends; turning from one to the other,
// the mix may not: there the camera steps back until the ball's disc (and
// the edge margin) fits the window, short of it by no more than the mix of
// what the two ends fall short (so that the move stays smooth at both).
void CameraFraming::keepBallInView(Aim &mixed, const Aim &from, const Aim &to, double x, int w, int h, double s) const {
  const double R = model_.ballRadius;
  const Vec3 ball = model_.path->at(s).centre(R);
  auto needed = [&](const Aim &aim) {
    const Lens lens = windowLens(window_, aim.fovDeg, double(w) / double(std::max(h, 1)));
    const ScreenAxes screen = screenAxes({aim.azimuth, aim.elevation}, lens.fovDeg, lens.aspect);
    const Vec3 d = ball - aim.target;
    double most = 0.0;
    for (int axis = 0; axis < 2; ++axis)
      most = std::max(most, d.dot(screen.toEye) + (std::abs(d.dot(screen.axes[axis])) + 1.3 * R) /
                                                      ((1.0 - kEdgeMargin) * screen.tans[axis]));
    return most;
  };
  const double shortFrom = std::max(0.0, needed(from) - from.distance),
               shortTo = std::max(0.0, needed(to) - to.distance);
  mixed.distance = std::max(mixed.distance, needed(mixed) - ((1.0 - x) * shortFrom + x * shortTo));
}

namespace {

// The box of ball centres (each padded by `pad`) in a window's NDC, seen
// with target t and distance d; the nearest depth among them.
struct NdcBox {
  double lo[2] = {1e30, 1e30}, hi[2] = {-1e30, -1e30};
  double nearest = 1e30;
};
NdcBox ndcBox(const std::vector<Vec3> &points, double pad, const ScreenAxes &screen, const Vec3 &t, double d) {
  NdcBox box;
  for (const Vec3 &p : points) {
    const double depth = d - (p - t).dot(screen.toEye);
    box.nearest = std::min(box.nearest, depth);
    for (int i = 0; i < 2; ++i) {
      const double at = (p - t).dot(screen.axes[i]), half = screen.tans[i] * std::max(depth, 1e-9);
      box.lo[i] = std::min(box.lo[i], (at - pad) / half), box.hi[i] = std::max(box.hi[i], (at + pad) / half);
    }
  }
  return box;
}

}  // namespace

// Closer by zooming about a point Q at the depth of the stretch's centre
// P: target and distance scale towards Q by c, so the stretch's picture
// grows about Q's place on screen. Q's place is chosen so that the
// stretch's box, grown by 1/c, stays inside the window (less the edge
// margin; no tighter than the whole clip's framing already holds it) and
// moves as little as it must from where that framing put it (the text laid
// out beside it keeps its room): it grows away from the edge it lies
// against. c goes down to where the ball at its farthest is
// kLeastBallShare of the view's height (times closeIn_), or to where the
// stretch no longer fits. c = 1 is the whole clip's framing itself, and c
// moves continuously with the camera's angles.
void CameraFraming::closeInOnStretch(const Shot &shot, const OrbitAngles &a, double fovDeg, double aspect, Vec3 &target,
                                     double &distance) const {
  // The ball's diameter over the view's height at depth d is
  // R / (d tan(fov/2)), the view's own lens (not the window's).
  const double R = model_.ballRadius, room = 1.0 - 1.5 * kEdgeMargin, pad = 1.3 * R;
  const double closest = R / (kLeastBallShare * std::tan(0.5 * shot.fovDeg * kDeg));
  std::vector<Vec3> centres;
  Vec3 P = Vec3::Zero();
  for (int i = 0; i <= 64; ++i) {
    centres.push_back(model_.path->at(shot.stretchStart + (shot.stretchEnd - shot.stretchStart) * i / 64.0).centre(R));
    P += centres.back() / 65.0;
  }
  const ScreenAxes screen = screenAxes(a, fovDeg, aspect);
  const NdcBox whole = ndcBox(centres, pad, screen, target, distance);
  double limLo[2], limHi[2];
  for (int i = 0; i < 2; ++i) limLo[i] = std::min(-room, whole.lo[i]), limHi[i] = std::max(room, whole.hi[i]);
  // (Seen from the eye moved towards Q, a centre p lies at the depth
  // (Q − p)·toEye + c × Q's depth, Q at P's: the farthest must come to `closest`.)
  const double depthOfP = distance - (P - target).dot(screen.toEye);
  double behindP = 0.0;
  for (const Vec3 &p : centres) behindP = std::max(behindP, (P - p).dot(screen.toEye));
  if (depthOfP + behindP <= closest) return;
  auto holds = [&](const std::pair<Vec3, double> &aim) {
    const NdcBox box = ndcBox(centres, pad, screen, aim.first, aim.second);
    return box.nearest > 2.0 * R && box.lo[0] >= limLo[0] - 1e-9 && box.hi[0] <= limHi[0] + 1e-9 &&
           box.lo[1] >= limLo[1] - 1e-9 && box.hi[1] <= limHi[1] + 1e-9;
  };
  auto scaled = [&](double c) {
    const double grow = 1.0 / c;
    Vec3 Q = P;
    for (int i = 0; i < 2; ++i) {
      const double centre = 0.5 * (whole.lo[i] + whole.hi[i]), half = 0.5 * (whole.hi[i] - whole.lo[i]) * grow;
      const double moved = 2.0 * half >= limHi[i] - limLo[i] ? 0.5 * (limLo[i] + limHi[i])
                                                             : std::clamp(centre, limLo[i] + half, limHi[i] - half);
      const double anchor = grow == 1.0 ? centre : (moved - grow * centre) / (1.0 - grow);  // the growth's fixed point
      const double atP = (P - target).dot(screen.axes[i]) / (screen.tans[i] * depthOfP);
      Q += (anchor - atP) * screen.tans[i] * depthOfP * screen.axes[i];
    }
    std::pair<Vec3, double> aim{Q + c * (target - Q), c * distance};
    // Nearer points grow faster than 1/c: pan what still lies past a limit
    // back in (a pan at P's depth moves nearer points more; a few rounds).
    for (int round = 0; round < 4; ++round) {
      const NdcBox box = ndcBox(centres, pad, screen, aim.first, aim.second);
      const double depthNow = aim.second - (P - aim.first).dot(screen.toEye);
      for (int i = 0; i < 2; ++i) {
        const double shift =
            box.lo[i] < limLo[i] ? limLo[i] - box.lo[i] : (box.hi[i] > limHi[i] ? limHi[i] - box.hi[i] : 0.0);
        aim.first -= shift * screen.tans[i] * depthNow * screen.axes[i];
      }
    }
    return aim;
  };
  // (Part of the way only, where the text asks: setCloseInShare.)
  const double goal = 1.0 - closeIn_ * (1.0 - std::max(0.05, (closest - behindP) / depthOfP));
  double least = goal, most = 1.0;  // the least scale that holds lies in (least, most]
  if (holds(scaled(goal))) most = goal;
  else
    for (int i = 0; i < 24; ++i) {
      const double mid = 0.5 * (least + most);
      (holds(scaled(mid)) ? most : least) = mid;
    }
  if (most < 1.0) std::tie(target, distance) = scaled(most);
}

}  // namespace rollspin::draw
