#include "motion/solve_job.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>

#include <fmt/format.h>

#include "spin/field.hpp"

namespace rollspin::motion {

namespace {
// The key a user would change to shorten the path: the first one given.
std::pair<std::string, SourceLoc> pathSizeKey(const scene::SceneSpec& spec) {
  if (spec.isStoryboard()) return {"segment", spec.where("segment")};
  for (const char* key : {"path.turns", "path.length", "path.radius", "path.colatitude_deg", "plate.radius"})
    if (spec.locations.contains(key)) return {key, spec.where(key)};
  return {"path", spec.where("path")};
}
// The steps grow like 1/R as the ball shrinks: when a ball of the path's own
// size would fit the limit, the radius is to blame. Name ball.radius where it
// was set and the smallest radius that fits (a bisection on log R: the
// budget falls monotonically as R grows).
void throwIfTheBallIsTooSmall(const scene::SceneSpec& spec, const RollingModel& model, double needed) {
  const double limit = static_cast<double>(scene::kMaxSolverSteps);
  auto stepsFor = [&](double radius) {
    return kAutomaticStepsPerRadian * spin::integratedStepBudget(*model.path, radius);
  };
  const double length = model.path->length();
  double fits = std::max(length, model.ballRadius);
  if (!(stepsFor(fits) <= limit)) return;  // the path itself is too long or too curved
  double tooSmall = model.ballRadius;
  for (int i = 0; i < 200 && fits > tooSmall * (1.0 + 1e-3); ++i) {
    const double mid = std::sqrt(fits) * std::sqrt(tooSmall);  // no overflow or underflow at the extremes
    (stepsFor(mid) <= limit ? fits : tooSmall) = mid;
  }
  throw badInput(spec.where("ball.radius"),
                 "ball.radius = {:g}: automatic stepping would need {:.3g} steps on this path (400 per radian the "
                 "ball turns), above the limit of 1e11; ball.radius must be at least {:.3g} here, or set solver.steps",
                 model.ballRadius, needed, fits);
}

// The clamped count for `needed` steps: at least 64, at most the limit (NaN too).
long long automaticCount(double needed) {
  if (!(needed <= static_cast<double>(scene::kMaxSolverSteps))) return scene::kMaxSolverSteps;
  return std::max<long long>(64, static_cast<long long>(std::ceil(needed)));
}

bool solverMethodGiven(const scene::SceneSpec& spec) { return spec.locations.contains("solver.method"); }

}  // namespace

SolverChoice chooseSolver(const scene::SceneSpec& spec, const RollingModel& model) {
  SolverChoice choice;
  const std::optional<spin::Method> method = spin::parseMethod(spec.solver.method);
  if (!method)  // a SceneSpec built in code, not by the loader
    throw badInput(spec.where("solver.method"), "solver.method: unknown method \"{}\"", spec.solver.method);
  choice.method = *method;
  // A storyboard is solved piece by piece: exact needs each piece constant,
  // and the message names the first segment that is not.
  const auto pieces = model.path->pieces();
  if (choice.method == spin::Method::Exact && pieces.empty() && !model.path->hasConstantCurvatures()) {
    throw badInput(spec.where("solver.method"),
                   "solver.method: \"exact\" needs a path with constant curvatures, but this path is a {}; "
                   "use \"magnus4\"",
                   model.path->describe());
  }
  for (std::size_t p = 0; choice.method == spin::Method::Exact && p < pieces.size(); ++p) {
    if (pieces[p].path->hasConstantCurvatures()) continue;
    // The piece's segment: the p-th motion (start < end; holds have no piece).
    std::size_t segment = 0, motions = 0;
    for (std::size_t k = 0; k < model.segments.size(); ++k) {
      if (!(model.segments[k].end > model.segments[k].start)) continue;
      if (motions++ == p) {
        segment = k;
        break;
      }
    }
    const std::string key = scene::SceneSpec::segmentKey(segment) + ".path";
    throw badInput(spec.where(solverMethodGiven(spec) ? "solver.method" : key),
                   "solver.method: \"exact\" needs constant curvatures in every segment, but {} is a {}, whose "
                   "curvatures vary; use \"magnus4\" (or \"frame6a\")",
                   key, pieces[p].path->describe());
  }
  const double length = model.path->length();
  if (!(std::isfinite(length) && length > 0.0)) {
    const auto [key, loc] = pathSizeKey(spec);
    throw badInput(loc, "{}: the path's length {} is not a finite positive number", key, length);
  }
  choice.automaticSteps = !spec.solver.steps.has_value();
  // ∫(|ω| + |d|) ds once: the automatic count and the estimate's round-off floor.
  choice.stepBudget = spin::integratedStepBudget(*model.path, model.ballRadius);
  if (spin::isAdaptive(choice.method)) {
    choice.automaticSteps = false;
    choice.tolerance = spec.solver.tolerance.value_or(scene::SolverSpec::kDefaultTolerance);
    return choice;
  }
  if (spec.solver.steps) {
    choice.steps = *spec.solver.steps;
  } else if (choice.method != spin::Method::Exact) {
    const double needed = kAutomaticStepsPerRadian * choice.stepBudget;
    if (!(needed <= static_cast<double>(scene::kMaxSolverSteps))) {
      throwIfTheBallIsTooSmall(spec, model, needed);
      const auto [key, loc] = pathSizeKey(spec);
      throw badInput(loc,
                     "{}: automatic stepping would need {:.3g} steps, above the limit of 1e11; shorten the "
                     "path or set solver.steps",
                     key, needed);
    }
    choice.steps = automaticCount(needed);
  }
  return choice;
}

double requiredAutomaticSteps(const RollingModel& model) {
  return kAutomaticStepsPerRadian * spin::integratedStepBudget(*model.path, model.ballRadius);
}

long long automaticSteps(const RollingModel& model, spin::Method method) {
  if (method == spin::Method::Exact) return 0;
  // magnus4's error per unit length scales like (h·rate)⁴ with the rate at
  // which the field is strong and turns (|ω| + |d|); h·rate = 1/400 keeps it
  // near 1e-13 per radian of rotation on the foundation's scenes (measured:
  // lollipop 5e-14, see tests). Other methods get the same grid: they are
  // baselines, and a user studying them sets solver.steps.
  return automaticCount(requiredAutomaticSteps(model));
}

long long defaultSampleCount(const RollingModel& model) {
  const double ballTurns = spin::integratedFieldStrength(*model.path, model.ballRadius) / (2.0 * std::numbers::pi);
  const double turns = std::max(model.path->turns(), ballTurns);
  // Clamp in floating point first: turns may be huge (or inf) on bad input.
  const double rows = std::clamp(std::ceil(60.0 * turns), 1.0, static_cast<double>(scene::kMaxTimelineSamples - 1));
  return static_cast<long long>(std::isfinite(rows) ? rows : 1.0) + 1;
}

spin::SampleArcLengths timelineArcLengths(const scene::SceneSpec& spec, const RollingModel& model) {
  const long long count = spec.timeline.samples ? *spec.timeline.samples : defaultSampleCount(model);
  return spin::SampleArcLengths::uniform(model.path->length(), static_cast<std::size_t>(count));
}

void addPathError(const RollingModel& model, const SolverChoice& choice, spin::SolveStats& stats) {
  // The solve and its coarse twin walk the same fitted path, so their
  // difference cannot see that path's own error; the same solve on a finer
  // approximation of the path (ContactPath::finerApproximation) differs from
  // this one by what that error does to U(L) (docs/solver.md#the-error-estimate).
  const auto start = std::chrono::steady_clock::now();
  const std::unique_ptr<geometry::ContactPath> finer = model.path->finerApproximation();
  if (!finer) return;
  const spin::SolveStats other =
      spin::Propagator(*finer, model.ballRadius, choice.method, choice.steps, choice.tolerance).solveFinal();
  stats.errorEstimate += other.status == spin::SolveStatus::Ok ? spin::rotationDistance(stats.final, other.final)
                                                               : std::numeric_limits<double>::infinity();
  stats.errorEstimateBasis +=
      " + the path's own error (difference to the same solve on the geodesic marched at half "
      "the step)";
  stats.errorEstimateSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

spin::SolveStats solveScene(const scene::SceneSpec& spec, const RollingModel& model, SolverChoice& choice) {
  // One propagator; the refinement's finer ones and the estimate's coarse one
  // share its segment budgets (withSteps: no second quadrature).
  const spin::Propagator first(*model.path, model.ballRadius, choice.method, choice.steps, choice.tolerance);
  auto solve = [&](long long steps) {
    spin::SolveStats stats = (steps == choice.steps ? first.solveFinal() : first.withSteps(steps).solveFinal());
    if (stats.status != spin::SolveStatus::Ok) {
      throw runtimeError(spec.where("solver.method"), "solver failed: {}", spin::statusMessage(stats.status));
    }
    return stats;
  };
  long long steps = choice.steps;
  spin::SolveStats stats = solve(steps);
  // solver.error_estimate = false: no second solve, so no estimate and no
  // refinement on it; the a priori count stands (docs/solver.md).
  if (!spec.solver.errorEstimate) {
    stats.errorEstimate = std::numeric_limits<double>::quiet_NaN();
    stats.errorEstimateBasis = std::string(kEstimateSkipped);
    stats.errorEstimateSeconds = 0.0;
    return stats;
  }
  const double budget =
      std::isfinite(choice.stepBudget) ? choice.stepBudget : spin::integratedStepBudget(*model.path, model.ballRadius);
  spin::estimateError(first, stats, budget);
  // Automatic steps: refine while the estimate says the a priori count fell
  // short. Each doubling reuses the previous solve as its coarse one, so the
  // estimate stays "against half the steps". It stops when the estimate no
  // longer falls (round-off dominates) or the step limit is near.
  if (choice.automaticSteps && choice.method != spin::Method::Exact) {
    double seconds = stats.seconds, estimateSeconds = stats.errorEstimateSeconds;
    for (int round = 0;
         round < 4 && stats.errorEstimate > kAutomaticEstimateTarget && steps <= scene::kMaxSolverSteps / 2; ++round) {
      spin::SolveStats finer = solve(2 * steps);
      finer.errorEstimate = spin::rotationDistance(finer.final, stats.final);
      finer.errorEstimateBasis =
          fmt::format("difference to {} at half the steps ({})", spin::methodName(choice.method), steps);
      estimateSeconds += seconds;
      seconds = finer.seconds;
      const bool falling = finer.errorEstimate < 0.5 * stats.errorEstimate;
      steps *= 2;
      stats = finer;
      if (!falling) break;
    }
    stats.errorEstimateSeconds = estimateSeconds;
    choice.steps = steps;
  }
  // After the refinement: more steps cannot shrink the path's own error.
  addPathError(model, choice, stats);
  return stats;
}

}  // namespace rollspin::motion
