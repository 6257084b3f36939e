// solver.tolerance and the issue-6 methods in scene files: a tolerance alone
// selects frame6a, the new method names load, and steps/tolerance given to
// the wrong kind of method are bad input naming the key.
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "model/rolling_model.hpp"
#include "motion/solve_job.hpp"
#include "scene/scene_loader.hpp"
#include "support/test_files.hpp"
#include "support/test_paths.hpp"

using namespace rollspin;

namespace {
scene::SceneSpec load(const std::vector<std::string>& sets) {
  return scene::loadSceneFile(rollspin::test::shippedScenePath("lollipop"), sets);
}
std::string badInputMessage(const std::vector<std::string>& sets) {
  try {
    (void)load(sets);
  } catch (const Error& e) {
    EXPECT_EQ(e.exitCode(), 2);
    return e.what();
  }
  return "no error";
}
}  // namespace

TEST(SolverTolerance, AToleranceAloneSelectsFrame6a) {
  const scene::SceneSpec spec = load({"solver.tolerance=1e-9"});
  EXPECT_EQ(spec.solver.method, "frame6a");
  const model::RollingModel model = model::buildModel(spec);
  const motion::SolverChoice choice = motion::chooseSolver(spec, model);
  EXPECT_EQ(choice.method, spin::Method::Frame6a);
  EXPECT_DOUBLE_EQ(choice.tolerance, 1e-9);
  const spin::SolveStats st = motion::solveScene(spec, model, choice);
  EXPECT_GT(st.steps, 0);
}

TEST(SolverTolerance, EveryMethodNameLoads) {
  for (const char* m : {"cf4", "magnus6", "rk45", "frame6a", "frame4"}) {
    const scene::SceneSpec spec = load({std::string("solver.method=") + m});
    const model::RollingModel model = model::buildModel(spec);
    const motion::SolverChoice choice = motion::chooseSolver(spec, model);
    EXPECT_EQ(spin::methodName(choice.method), m);
    if (spin::isAdaptive(choice.method)) {
      EXPECT_DOUBLE_EQ(choice.tolerance, scene::SolverSpec::kDefaultTolerance);
    }
  }
}

TEST(SolverTolerance, WrongKindOfMethodIsBadInput) {
  EXPECT_NE(badInputMessage({"solver.method=magnus4", "solver.tolerance=1e-8"}).find("solver.tolerance"),
            std::string::npos);
  EXPECT_NE(badInputMessage({"solver.method=rk45", "solver.steps=100"}).find("solver.steps"), std::string::npos);
  EXPECT_NE(badInputMessage({"solver.tolerance=0"}).find("[1e-15, 1]"), std::string::npos);
  EXPECT_NE(badInputMessage({"solver.tolerance=2"}).find("[1e-15, 1]"), std::string::npos);
}
