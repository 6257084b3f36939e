// Frame poses: what one image needs from the solver (the ball's U(s), the
// trail's and the strobe's samples) and the sampling policy that says which
// arc lengths those are. The solving side owns these; drawing consumes them.
#pragma once

#include <cstddef>
#include <vector>

#include "model/rolling_model.hpp"
#include "motion/frame_clock.hpp"
#include "scene/scene_spec.hpp"
#include "spin/su2.hpp"

namespace rollspin::motion {

using model::RollingModel;

struct OrientedSample {
  double s = 0.0;
  spin::Su2 q;  // U(s): worldFromBody
};

// Everything time-dependent one image needs.
struct FrameOrientations {
  OrientedSample current;              // the ball (and the twin's arrows) at s
  StoryPlace story;                    // a storyboard's segment (caption, title, camera) and its time
  std::vector<OrientedSample> trail;   // U on [0, s], increasing s, for the Bloch trail
  std::vector<OrientedSample> strobe;  // render.strobe > 1: the extra ball positions
  std::vector<OrientedSample> cuts;    // a scene of several surfaces: U where each new surface begins (cutArcLengths)
  // A single image (render --still): no later frame will show the circuit's
  // end values, so its fact labels show them beside the values at s.
  bool still = false;
};

// The trail's fixed grid g_i = L·i/(count − 1), i = 0 … count − 1 (g_last =
// L exactly): ≥ 240 points over the path, 120 per turn, at most 20001. The
// trail of the frame at s is {g_i < s} ∪ {s} (plus g_0 when s = 0), so every
// frame's trail is a prefix of one sequence: one march serves a whole clip,
// and a trail's vertices stay put from frame to frame instead of sliding.
struct TrailGrid {
  double length = 0.0;
  std::size_t count = 0;  // 0 when render.trails = false
  [[nodiscard]] double at(std::size_t i) const {
    return i + 1 == count ? length : length * double(i) / double(count - 1);
  }
};
[[nodiscard]] TrailGrid trailGrid(const scene::SceneSpec& spec, const RollingModel& model);

// Arc lengths the solver must report for a still at `s`: the trail samples
// (above) and the strobe positions (sorted, inside [0, L]).
struct FrameSampling {
  std::vector<double> trail;
  std::vector<double> strobe;
};
[[nodiscard]] FrameSampling frameSampling(const scene::SceneSpec& spec, const RollingModel& model, double s);
// The strobe positions alone (empty unless render.strobe > 1).
[[nodiscard]] std::vector<double> strobeArcLengths(const scene::SceneSpec& spec, const RollingModel& model);

// Where a storyboard's surface changes: the start of each motion whose
// surface differs from the previous motion's, increasing (empty for a scene
// of one surface). A cross-fade shows the ball there as it left the old
// surface.
[[nodiscard]] std::vector<double> cutArcLengths(const RollingModel& model);

// Runs the propagator once for the frame's arc lengths (trail, strobe, cuts, s).
[[nodiscard]] FrameOrientations solveFrame(const scene::SceneSpec& spec, const RollingModel& model, double s);

// The animation's clock: the scene's path, or its storyboard's segments.
[[nodiscard]] FrameClock clipClock(const scene::SceneSpec& spec, const RollingModel& model);
// Which storyboard segment a still at s shows: the motion that starts last
// at or before s (a join shows the segment starting there).
[[nodiscard]] StoryPlace storyPlaceAt(const RollingModel& model, double s);

}  // namespace rollspin::motion
