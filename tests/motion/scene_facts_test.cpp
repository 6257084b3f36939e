// Scene facts (the numbers the gallery's labels print) against independent
// numbers: the kinematic oracle (src/kinematics, which never sees a spinor or
// a curvature) and closed forms that tests/spin/oracle_test.cpp verifies
// against it. Each scene is the file in scenes/, as the gallery renders it.
#include "motion/scene_facts.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "kinematics/rolling_kinematics.hpp"
#include "motion/solve_job.hpp"
#include "spin/field.hpp"
#include "spin/propagator.hpp"
#include "support/cli_runner.hpp"
#include "support/numbers.hpp"

using namespace rollspin;
using motion::SceneFacts;
using rollspin::test::kPi;
using scene::Fact;

namespace {

struct Loaded {
  scene::SceneSpec spec;
  model::RollingModel model;
};

Loaded load(const std::string& name, const std::vector<std::string>& overrides = {}) {
  Loaded l;
  l.spec = model::loadScene((test::sourceDir() / "scenes" / (name + ".toml")).string(), overrides);
  l.model = model::buildSceneModel(l.spec);
  return l;
}

// U(s) from the scene's own solver at one arc length.
spin::Su2 solverAt(const Loaded& l, double s) {
  const motion::SolverChoice c = motion::chooseSolver(l.spec, l.model);
  spin::Su2 out;
  const std::vector<double> at{s};
  (void)spin::Propagator(*l.model.path, l.model.ballRadius, c.method, c.steps, c.tolerance)
      .run(at, [&](std::size_t, double, const spin::Su2& q) { out = q; });
  return out;
}

// Rotation angle in [0, π] of a rotation matrix, via atan2 (as rotationAngleAxis).
double matrixAngle(const Eigen::Matrix3d& m) {
  const Eigen::AngleAxisd aa(m);
  return std::abs(std::remainder(aa.angle(), 2 * kPi));
}

}  // namespace

TEST(SceneFacts, AutoChoosesEachGalleryScenesFact) {
  EXPECT_EQ(scene::resolveFacts(load("lollipop").spec), (std::vector<Fact>{Fact::Delta}));
  EXPECT_EQ(scene::resolveFacts(load("tennis-ball").spec), (std::vector<Fact>{Fact::Marks}));
  EXPECT_EQ(scene::resolveFacts(load("penny").spec), (std::vector<Fact>{Fact::Turns}));
  EXPECT_EQ(scene::resolveFacts(load("berry").spec), (std::vector<Fact>{Fact::PhaseSplit}));
  EXPECT_EQ(scene::resolveFacts(load("sphere-outside").spec), (std::vector<Fact>{Fact::Delta}));
  EXPECT_TRUE(scene::resolveFacts(load("torus").spec).empty());
  EXPECT_TRUE(scene::resolveFacts(load("lollipop", {"labels.facts=none"}).spec).empty());
  EXPECT_EQ(scene::resolveFacts(load("lollipop", {R"(labels.facts=["phase-split", "delta"])"}).spec),
            (std::vector<Fact>{Fact::PhaseSplit, Fact::Delta}));
}

TEST(SceneFacts, AFactThatDoesNotApplyIsBadInputNamingTheKey) {
  try {
    (void)load("lollipop", {R"(labels.facts=["turns"])"});
    FAIL() << "expected BadInput";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("labels.facts"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("colatitude_deg = 90"), std::string::npos) << e.what();
  }
  for (const char* bad : {"labels.facts=sometimes", R"(labels.facts=["delta", "delta"])", "labels.facts=3"})
    EXPECT_THROW((void)load("lollipop", {bad}), Error) << bad;
}

TEST(SceneFacts, LollipopDeltaMatchesTheClosedFormAndTheOracle) {
  for (const auto& [R, r] : {std::pair{"1.0", "3.0"}, {"0.5", "2.0"}, {"1.0", "1.0"}}) {
    const Loaded l = load("lollipop", {std::string("ball.radius=") + R, std::string("path.radius=") + r});
    const SceneFacts f(l.spec, l.model, {Fact::Delta});
    ASSERT_TRUE(f.delta);
    const double Rv = std::stod(R), rv = std::stod(r);
    const double closed = 2 * kPi * std::sqrt(1 + (rv / Rv) * (rv / Rv));
    EXPECT_NEAR(f.delta->closedForm, closed, 1e-12);
    EXPECT_NEAR(f.delta->measured, closed, 1e-9) << "R=" << R << " r=" << r;
    // The lab rotation is δ modulo 2π, and the kinematic oracle agrees.
    EXPECT_NEAR(f.delta->labAngle, f.delta->closedFormMod, 1e-9);
    const kinematics::RollingKinematics kin(*l.model.path, l.model.ballRadius, {40000, 0.0});
    EXPECT_NEAR(matrixAngle(kin.finalOrientation()), f.delta->closedFormMod, 1e-8);
    // Live: the rolling-frame angle grows linearly on a circle.
    const double half = 0.5 * l.model.path->length();
    EXPECT_NEAR(f.at(half, solverAt(l, half)).rolling, 0.5 * closed, 1e-9);
  }
}

TEST(SceneFacts, SphereDeltaIsTheDerivedFormulaInsideAndOut) {
  for (const char* name : {"sphere-outside", "sphere-inside"}) {
    const Loaded l = load(name);
    const SceneFacts f(l.spec, l.model, {Fact::Delta});
    const double th = l.spec.path.colatitudeDeg * kPi / 180, rho = l.spec.surface.number("radius") * std::sin(th);
    const double R = l.spec.ball.radius;
    EXPECT_NEAR(f.delta->measured, 2 * kPi * std::sqrt(rho * rho / (R * R) + std::cos(th) * std::cos(th)), 1e-9)
        << name;
    const kinematics::RollingKinematics kin(*l.model.path, R, {40000, 0.0});
    EXPECT_NEAR(matrixAngle(kin.finalOrientation()), f.delta->closedFormMod, 1e-8) << name;
  }
}

TEST(SceneFacts, PennyTurnsTwiceInTheLabAndThreeTimesAgainstTheRadiusLine) {
  const Loaded l = load("penny");
  const SceneFacts f(l.spec, l.model, scene::resolveFacts(l.spec));
  ASSERT_TRUE(f.turns);
  EXPECT_TRUE(f.turns->paperPenny);
  EXPECT_NEAR(f.turns->lab / (2 * kPi), -2.0, 1e-9);  // against the revolution
  EXPECT_NEAR(f.turns->frame / (2 * kPi), 1.0, 1e-9);
  EXPECT_NEAR((f.turns->lab - f.turns->frame) / (2 * kPi), -3.0, 1e-9);
  // The oracle's own lab angle ∫ ω·ẑ ds (ω from finite differences of C(s)).
  const kinematics::RollingKinematics kin(*l.model.path, l.model.ballRadius, {40000, 0.0});
  double oracleLab = 0.0;
  const int n = 2000;
  const double L = l.model.path->length();
  for (int i = 0; i < n; ++i) oracleLab += 0.5 * (kin.omega(L * i / n).z() + kin.omega(L * (i + 1) / n).z()) * L / n;
  EXPECT_NEAR(f.turns->lab, oracleLab, 1e-9);
  // Live counts part-way: ω is constant, so a third of the way is a third of each count.
  const double third = L / 3;
  const motion::LiveAngles a = f.at(third, solverAt(l, third));
  EXPECT_NEAR(a.lab / (2 * kPi), -2.0 / 3, 1e-9);
  EXPECT_NEAR((a.lab - a.frame) / (2 * kPi), -1.0, 1e-9);
}

TEST(SceneFacts, TennisBallTurnsByPiBetweenMarks) {
  const Loaded l = load("tennis-ball");
  const SceneFacts f(l.spec, l.model, scene::resolveFacts(l.spec));
  ASSERT_TRUE(f.marks);
  EXPECT_NEAR(f.marks->beta, kPi / std::sqrt(2.0), 1e-15);  // r = R
  // One circuit holds the marks at 0, β and 2β (3β = 382° is past it).
  ASSERT_EQ(f.marks->s.size(), 3u);
  for (std::size_t k = 0; k < f.marks->turn.size(); ++k) {
    EXPECT_NEAR(f.marks->turn[k], kPi, 1e-9) << k;
    EXPECT_NEAR(f.marks->axisFromNormal[k], kPi / 4, 1e-9) << k;  // the moving 45° axis
  }
  EXPECT_EQ(f.marksPassed(0.0), 1);
  EXPECT_EQ(f.marksPassed(f.marks->s[1]), 2);
  EXPECT_EQ(f.marksPassed(l.model.path->length()), 3);
  // Another radius: β = π/√(1 + (r/R)²) still turns by π (plate R1 = 3: r = 1.5).
  const Loaded wide = load("tennis-ball", {"plate.radius=3", "path.turns=2"});
  const SceneFacts g(wide.spec, wide.model, {Fact::Marks});
  EXPECT_NEAR(g.marks->beta, kPi / std::sqrt(1 + 1.5 * 1.5), 1e-15);
  EXPECT_GT(g.marks->turn.size(), 5u);
  for (double t : g.marks->turn) EXPECT_NEAR(t, kPi, 1e-9);
}

TEST(SceneFacts, TennisBallMarkOrientationsMatchTheOracle) {
  // The kinematic oracle's Q at consecutive marks, carried along with the
  // path (Rot(n, β)), differs by a half turn: Q_{k+1} (Rot(n, β) Q_k)ᵀ = π.
  const Loaded l = load("tennis-ball");
  const SceneFacts f(l.spec, l.model, {Fact::Marks});
  const kinematics::RollingKinematics kin(*l.model.path, l.model.ballRadius, {40000, 0.0});
  const auto q = kin.orientations(f.marks->s);
  const Eigen::Matrix3d carry = Eigen::AngleAxisd(f.marks->beta, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  for (std::size_t k = 0; k + 1 < q.size(); ++k)
    EXPECT_NEAR(Eigen::AngleAxisd(Eigen::Matrix3d(q[k + 1] * (carry * q[k]).transpose())).angle(), kPi, 1e-8) << k;
}

TEST(SceneFacts, BerrySplitSumsToTheTotalPhase) {
  const Loaded l = load("berry");
  const SceneFacts f(l.spec, l.model, scene::resolveFacts(l.spec));
  ASSERT_TRUE(f.phaseSplit);
  const auto& p = *f.phaseSplit;
  EXPECT_LT(std::abs(p.residual), 1e-9);  // Aharonov–Anandan: exact for the cyclic spin
  // The geometric part is not trivially zero, and the split is not an identity
  // of the numbers: the other sign of Ω breaks it.
  EXPECT_GT(std::abs(p.geometric), 0.5);
  EXPECT_GT(std::abs(std::remainder(p.total - p.dynamic + p.geometric, 2 * kPi)), 0.1);
  // Berry's cone: quadrature against 2π(1 − cos α), α = 90° − θ for B ∥ e_θ outside a sphere.
  EXPECT_NEAR(p.coneAngle, kPi / 2 - l.spec.path.colatitudeDeg * kPi / 180, 1e-12);
  EXPECT_NEAR(p.berryGeometric, p.berryClosedForm, 1e-10);
  // Small ball (R/r = 0.05): the cyclic spin is nearly along B and the split
  // is nearly Berry's: the residual of the adiabatic split is O(R/r).
  EXPECT_LT(p.spinFromField, 0.1);
  const double adiabaticGap = std::abs(std::remainder(p.adiabaticDynamic + p.berryGeometric - p.total, 2 * kPi));
  EXPECT_LT(adiabaticGap, 0.1);
  // ... and shrinks with R/r.
  const Loaded smaller = load("berry", {"ball.radius=0.025"});
  const SceneFacts g(smaller.spec, smaller.model, {Fact::PhaseSplit});
  const double smallerGap = std::abs(
      std::remainder(g.phaseSplit->adiabaticDynamic + g.phaseSplit->berryGeometric - g.phaseSplit->total, 2 * kPi));
  EXPECT_LT(smallerGap, 0.3 * adiabaticGap);
  EXPECT_LT(std::abs(g.phaseSplit->residual), 1e-9);
}

TEST(SceneFacts, PhaseSplitOnTheLollipopWhereBSweepsAGreatCircle) {
  // On a plane B = −u/R lies in the floor: its loop is the equator (Ω = 2π,
  // Berry's −Ω/2 = −π mod 2π), and the mean direction of the loop vanishes.
  const Loaded l = load("lollipop", {R"(labels.facts=["phase-split"])"});
  const SceneFacts f(l.spec, l.model, scene::resolveFacts(l.spec));
  const auto& p = *f.phaseSplit;
  EXPECT_NEAR(p.coneAngle, kPi / 2, 1e-12);
  EXPECT_NEAR(std::abs(std::remainder(p.berryGeometric, 2 * kPi)), kPi, 1e-10);
  EXPECT_NEAR(p.berryGeometric, p.berryClosedForm, 1e-10);
  EXPECT_LT(std::abs(p.residual), 1e-9);
  EXPECT_TRUE(std::isfinite(p.geometric) && std::isfinite(p.dynamic));
}

TEST(SceneFacts, PrintShowsWhatAutoChoseAndReadsBack) {
  const std::string berry = (test::sourceDir() / "scenes" / "berry.toml").string();
  const auto printed = test::runRollspin({"scene", berry, "--print"});
  ASSERT_EQ(printed.exitCode, 0) << printed.err;
  EXPECT_NE(printed.out.find("[labels]\nfacts = \"auto\"  # for this scene: phase-split\n"), std::string::npos)
      << printed.out;
  const auto none = test::runRollspin({"scene", berry, "--print", "--set", "labels.facts=none"});
  EXPECT_NE(none.out.find("facts = \"none\"\n"), std::string::npos) << none.out;
  const auto bad = test::runRollspin({"scene", berry, "--print", "--set", R"(labels.facts=["marks"])"});
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_NE(bad.err.find("labels.facts: \"marks\" applies to a circle on a plane only"), std::string::npos) << bad.err;
}

TEST(SceneFacts, OneNumberChangedStillMatches) {
  // A lecturer changes one number: direction, turns, radii.
  {
    const Loaded l = load("lollipop", {"path.direction=cw", "path.turns=2.5"});
    const SceneFacts f(l.spec, l.model, {Fact::Delta});
    EXPECT_NEAR(f.delta->measured, 2.5 * 2 * kPi * std::sqrt(10.0), 1e-9);
    EXPECT_NEAR(f.delta->closedForm, f.delta->measured, 1e-9);
    EXPECT_FALSE(f.delta->wholeCircuits);  // U(L) also holds the frame's half turn: no mod-2π check
  }
  {
    const Loaded l = load("lollipop", {"path.direction=cw", "path.turns=3"});
    const SceneFacts f(l.spec, l.model, {Fact::Delta});
    EXPECT_NEAR(f.delta->measured, 3 * 2 * kPi * std::sqrt(10.0), 1e-9);
    EXPECT_NEAR(f.delta->labAngle, f.delta->closedFormMod, 1e-9);
  }
  {
    const Loaded l = load("tennis-ball", {"path.direction=cw"});
    const SceneFacts f(l.spec, l.model, {Fact::Marks});
    for (double t : f.marks->turn) EXPECT_NEAR(t, kPi, 1e-9);
  }
  {
    const Loaded l = load("penny", {"path.direction=cw", "path.turns=2"});
    const SceneFacts f(l.spec, l.model, {Fact::Turns});
    EXPECT_NEAR(std::abs(f.turns->lab) / (2 * kPi), 4.0, 1e-9);
    EXPECT_NEAR(std::abs(f.turns->lab - f.turns->frame) / (2 * kPi), 6.0, 1e-9);
    EXPECT_LT(f.turns->lab * f.turns->frame, 0.0);  // still against the revolution
    EXPECT_FALSE(f.turns->paperPenny);              // two circuits: not the paper's statement
  }
  {
    // Outside, at the equator: the lab turns with the revolution, 1 + r/R... (ω = (1/R)(1 + R/r) u).
    const Loaded l = load("penny", {"surface.side=outside"});
    const SceneFacts f(l.spec, l.model, {Fact::Turns});
    EXPECT_NEAR(std::abs(f.turns->lab) / (2 * kPi), (1.0 + 1.0 / 3.0) * 3.0, 1e-9);  // ∫|ω| ds / 2π = (4/3)(6π)/2π
  }
}
