// What a solve needs from a scene: the method, the step count (automatic
// unless the scene sets solver.steps) and the timeline's sample arc lengths.
#pragma once

#include <limits>
#include <string_view>
#include <vector>

#include "model/rolling_model.hpp"
#include "scene/scene_spec.hpp"
#include "spin/propagator.hpp"

namespace rollspin::motion {

using model::RollingModel;
using model::SegmentSpan;

struct SolverChoice {
  spin::Method method = spin::Method::Magnus4;
  long long steps = 0;
  bool automaticSteps = true;
  double tolerance = 0.0;  // adaptive methods (rk45, frame6a)
  // ∫(|ω| + |d|) ds along the path (spin::integratedStepBudget), computed
  // once by chooseSolver: the automatic count and the estimate's floor.
  double stepBudget = std::numeric_limits<double>::quiet_NaN();
};

// Automatic steps per radian of ∫(|ω| + |d|) ds.
inline constexpr double kAutomaticStepsPerRadian = 400.0;

// Throws BadInput (at solver.method) when 'exact' is asked for a path with
// varying curvatures.
[[nodiscard]] SolverChoice chooseSolver(const scene::SceneSpec& spec, const RollingModel& model);

// Automatic step count: 400 per unit of ∫(|ω| + |d|) ds, so that magnus4
// reaches ~1e-13 per radian on smooth paths; the propagator shares them
// among breakpoint segments by the same integral, so corner arcs of any
// radius get the steps their turn needs (docs/solver.md).
[[nodiscard]] long long automaticSteps(const RollingModel& model, spin::Method method);
// The unclamped automatic step count (may exceed the limit, or be inf/NaN).
[[nodiscard]] double requiredAutomaticSteps(const RollingModel& model);

// Default sample count: 60 per turn of the path or of the ball, whichever is
// more, plus the end point.
[[nodiscard]] long long defaultSampleCount(const RollingModel& model);
[[nodiscard]] spin::SampleArcLengths timelineArcLengths(const scene::SceneSpec& spec, const RollingModel& model);

// Runs the solver for its final value and statistics, with the a
// posteriori error estimate (spin::estimateError: stats.errorEstimate,
// errorEstimateBasis, errorEstimateSeconds). With automatic steps the count
// is doubled (up to 4 times, the previous solve serving as the coarse one)
// while the estimate exceeds kAutomaticEstimateTarget and keeps falling, so
// "automatic" is accurate even where the a priori count falls short.
// Throws Runtime on a non-finite result.
inline constexpr double kAutomaticEstimateTarget = 1e-10;
// `choice.steps` becomes the count used. With solver.error_estimate = false
// no estimate is made (errorEstimate NaN, basis kEstimateSkipped, no
// refinement).
inline constexpr std::string_view kEstimateSkipped = "skipped (solver.error_estimate = false)";
[[nodiscard]] spin::SolveStats solveScene(const scene::SceneSpec& spec, const RollingModel& model,
                                          SolverChoice& choice);
// Adds to stats.errorEstimate (its basis and seconds) the path's own error,
// which no step count of the spinor can see or reduce: the rotation distance
// to the same solve (method, steps, tolerance of `choice`) on the path's
// finer approximation (a geodesic marched at half the step, not fitted).
// Nothing for paths that have none. solveScene calls it last.
void addPathError(const RollingModel& model, const SolverChoice& choice, spin::SolveStats& stats);
// The same, for a caller that does not need the count used.
[[nodiscard]] inline spin::SolveStats solveScene(const scene::SceneSpec& spec, const RollingModel& model,
                                                 const SolverChoice& choice) {
  SolverChoice used = choice;
  return solveScene(spec, model, used);
}

}  // namespace rollspin::motion
