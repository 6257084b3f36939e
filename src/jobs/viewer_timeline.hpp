// The web viewer's timeline: the solver's samples of q(s) with the field
// B(s) and the ball's centre C(s) with dC/ds, dense enough that the viewer's
// cubic Hermite interpolation between them, with the derivatives
//   dq/ds = −½ (0, B) ⊗ q            (dU/ds = −(i/2) ω·σ U, B = −ω)
//   dC/ds = (1 − κ_n R) t − R τ_g u  (C = P + R n, the Darboux equations)
// agrees with the solver at any s to well below 1e-7. Knots fall on every
// breakpoint of the path and every storyboard join, with a twin knot just
// before each (the one-sided field), so no interval straddles a jump of B.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "model/rolling_model.hpp"
#include "motion/solve_job.hpp"
#include "scene/scene_spec.hpp"

namespace rollspin::jobs {

// How far before a breakpoint its twin knot lies, relative to the length:
// the interval between them is too short for the jump of B to matter (its
// Hermite error is ~ this × |ΔB| × the spacing's share).
inline constexpr double kTwinKnotGap = 1e-10;

// The knot spacing h: (|B| + 2√|dB/ds|) h at most this, so the spinor turns
// at most 0.1 rad between knots and the field swings little (Hermite's error
// is ~(|B| h / 2)⁴ / 384 per unit of q for a steady field, 1.6e-9 at 0.1).
inline constexpr double kViewerKnotRadians = 0.1;
// Whatever the field, at least this many knots along the whole path.
inline constexpr std::size_t kViewerLeastKnots = 200;

struct ViewerKnot {
  double s = 0.0;
  std::array<double, 4> q{};  // qw, qx, qy, qz as the timeline writes them (sign kept)
  std::array<double, 3> b{};  // the field B(s) on the side of the interval after s
  std::array<double, 3> centre{}, centreRate{};
};

// A storyboard segment as the viewer shows it: a chapter.
struct ViewerChapter {
  std::size_t number = 0;  // from 1, as the timeline's `segment` column
  double start = 0.0, end = 0.0;
  std::string caption, title;
  std::size_t surface = 0;  // the surface stretch it is on: GLB node "surface" (0), "surface.1", …
  // Where the ball view looks from in this segment, [azimuth, elevation] in
  // degrees: render.azimuth_deg / elevation_deg with each segment's camera
  // keys laid over the previous segment's, as the renders' storyboard does.
  std::array<double, 2> viewDeg{};
};

// The clip's clock (motion::FrameClock) as pieces in the clip's seconds:
// piece k runs from seconds[k] to seconds[k + 1] and shows
//   s(t) = s0[k] + (s1[k] − s0[k]) · ease((t − seconds[k]) / (seconds[k + 1] − seconds[k]))
// (ease: x, or 3x² − 2x³ when smooth), a hold where s0 = s1. A hold at a
// surface change that still shows the earlier surface holds a hair before
// the join (kTwinKnotGap · L), so that s names the surface the clip shows.
struct ViewerClock {
  std::vector<double> seconds;       // the pieces' bounds, from 0 to the clip's last frame
  std::vector<double> s0, s1;        // one per piece
  std::vector<std::size_t> segment;  // one per piece: the scene segment it shows (0 without a storyboard)
  bool smooth = true;
};

struct ViewerTimeline {
  double length = 0.0, ballRadius = 1.0;
  std::array<double, 3> marker{};   // the body point whose image is the Bloch vector
  std::array<double, 2> viewDeg{};  // render.azimuth_deg, render.elevation_deg: where the views look from
  std::vector<ViewerKnot> knots;
  std::vector<ViewerChapter> chapters;  // empty unless a storyboard
  ViewerClock clock;
};

// The knot arc lengths: sorted, from 0 to the length, on every breakpoint.
[[nodiscard]] std::vector<double> viewerKnotArcLengths(const model::RollingModel& model);

// Solves along the path (the timeline's own sampling, jobs/timeline_csv.hpp)
// at the knots. Throws Runtime when the solver fails.
[[nodiscard]] ViewerTimeline sampleViewerTimeline(const scene::SceneSpec& spec, const model::RollingModel& model,
                                                  const motion::SolverChoice& choice);

// The timeline as the JSON object the viewer reads (web/src/timeline.js).
[[nodiscard]] std::string viewerTimelineJson(const ViewerTimeline& timeline);

}  // namespace rollspin::jobs
