#include "app/solve_job.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "spin/field.hpp"

namespace rollspin::app {

SolverChoice chooseSolver(const scene::SceneSpec& spec, const RollingModel& model) {
  SolverChoice choice;
  choice.method = *spin::parseMethod(spec.solver.method);  // validated by the loader
  if (choice.method == spin::Method::Exact && !model.path->hasConstantCurvatures()) {
    throw badInput(spec.where("solver.method"),
                   "solver.method: \"exact\" needs a path with constant curvatures, but this path is a {}; "
                   "use \"magnus4\"",
                   model.path->describe());
  }
  choice.automaticSteps = !spec.solver.steps.has_value();
  if (spin::isAdaptive(choice.method)) {
    choice.automaticSteps = false;
    choice.tolerance = spec.solver.tolerance.value_or(scene::SolverSpec::kDefaultTolerance);
    return choice;
  }
  choice.steps = spec.solver.steps ? *spec.solver.steps : automaticSteps(model, choice.method);
  return choice;
}

long long automaticSteps(const RollingModel& model, spin::Method method) {
  if (method == spin::Method::Exact) return 0;
  // magnus4's error per unit length scales like (h·rate)⁴ with the rate at
  // which the field is strong and turns (|ω| + |d|); h·rate = 1/400 keeps it
  // near 1e-13 per radian of rotation on the foundation's scenes (measured:
  // lollipop 5e-14, see tests). Other methods get the same grid: they are
  // baselines, and a user studying them sets solver.steps.
  const double budget = spin::integratedStepBudget(*model.path, model.ballRadius);
  return std::clamp<long long>(static_cast<long long>(std::ceil(400.0 * budget)), 64, 100'000'000);
}

long long defaultSampleCount(const RollingModel& model) {
  const double ballTurns = spin::integratedFieldStrength(*model.path, model.ballRadius) / (2.0 * std::numbers::pi);
  const double turns = std::max(model.path->turns(), ballTurns);
  return std::clamp<long long>(static_cast<long long>(std::ceil(60.0 * turns)), 1, 100'000'000) + 1;
}

std::vector<double> timelineArcLengths(const scene::SceneSpec& spec, const RollingModel& model) {
  const long long count = spec.timeline.samples ? *spec.timeline.samples : defaultSampleCount(model);
  return spin::uniformSamples(model.path->length(), static_cast<std::size_t>(count));
}

spin::SolveStats solveScene(const scene::SceneSpec& spec, const RollingModel& model, const SolverChoice& choice) {
  const spin::Propagator propagator(*model.path, model.ballRadius, choice.method, choice.steps, choice.tolerance);
  spin::SolveStats stats = propagator.solveFinal();
  if (stats.status != spin::SolveStatus::Ok) {
    throw runtimeError(spec.where("solver.method"), "solver failed: {}", spin::statusMessage(stats.status));
  }
  return stats;
}

}  // namespace rollspin::app
