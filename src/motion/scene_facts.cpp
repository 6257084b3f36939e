#include "motion/scene_facts.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

#include "core/error.hpp"
#include "core/stage_log.hpp"
#include "motion/solve_job.hpp"
#include "spin/closed_forms.hpp"
#include "spin/field.hpp"
#include "spin/propagator.hpp"

namespace rollspin::motion {

namespace closed_form = spin::closed_form;

namespace {

using geometry::Vec3;
using scene::Fact;
using spin::Su2;
constexpr double kPi = std::numbers::pi;

double wrapAngle(double a) { return std::remainder(a, 2.0 * kPi); }

double dot4(const Su2& a, const Su2& b) { return a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z; }

// The Darboux frame's turn F(s) F(0)ᵀ as a spinor with the sign nearer `near`
// (F = [t u n] as columns).
Su2 frameTurn(const geometry::DarbouxSample& f, const spin::Mat3& f0Transposed, const Su2& near) {
  spin::Mat3 frame;
  frame.col(0) = f.tangent;
  frame.col(1) = f.tangentNormal;
  frame.col(2) = f.normal;
  const Eigen::Quaterniond q(spin::Mat3(frame * f0Transposed));
  Su2 w{q.w(), q.x(), q.y(), q.z()};
  return dot4(w, near) < 0.0 ? -w : w;
}

spin::Mat3 startFrameTransposed(const geometry::ContactPath& path) {
  const geometry::DarbouxSample f0 = path.at(0.0);
  spin::Mat3 frame;
  frame.col(0) = f0.tangent;
  frame.col(1) = f0.tangentNormal;
  frame.col(2) = f0.normal;
  return frame.transpose();
}

// U at each s (non-decreasing) from one run of the scene's solver.
std::vector<Su2> solveAt(const scene::SceneSpec& spec, const RollingModel& model, const std::vector<double>& s) {
  const SolverChoice choice = chooseSolver(spec, model);
  const spin::Propagator propagator(*model.path, model.ballRadius, choice.method, choice.steps, choice.tolerance);
  std::vector<Su2> out(s.size());
  const spin::SolveStats stats = propagator.run(s, [&](std::size_t i, double, const Su2& q) { out[i] = q; });
  if (stats.status != spin::SolveStatus::Ok)
    throw runtimeError(spec.where("solver.method"), "solver failed: {}", spin::statusMessage(stats.status));
  return out;
}

// Circle radius r on a plane: the plate's contact circle R1/2 (derived by the
// model), else path.radius; both are 1/|κ_g|.
double planeCircleRadius(const RollingModel& model) { return 1.0 / std::abs(model.path->at(0.0).geodesicCurvature); }

// Composite 8-point Gauss–Legendre nodes and weights on [0, L] in `panels`.
void gaussNodes(double length, int panels, std::vector<double>& nodes, std::vector<double>& weights) {
  static constexpr double x[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363};
  static constexpr double w[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};
  const double h = length / panels;
  for (int p = 0; p < panels; ++p) {
    const double mid = (p + 0.5) * h;
    for (int side : {-1, 1})
      for (int k = 0; k < 4; ++k) {
        const int j = side < 0 ? 3 - k : k;  // increasing order
        nodes.push_back(mid + side * x[j] * 0.5 * h);
        weights.push_back(w[j] * 0.5 * h);
      }
  }
}

// Ω = ∮ c·(X × X')/(1 + X·c) ds: the solid angle a closed loop X(s) encloses
// about the unit direction c (right-handed), for a loop that keeps away from −c.
double solidAngleTerm(const Vec3& x, const Vec3& dx, const Vec3& c) { return c.dot(x.cross(dx)) / (1.0 + x.dot(c)); }

}  // namespace

Vec3 incrementRotation(const Su2& q0) {
  const Su2 q = q0.w < 0.0 ? -q0 : q0;
  const Vec3 v = q.vec();
  const double n = v.norm();
  if (n == 0.0) return Vec3::Zero();
  return (2.0 * std::atan2(n, q.w) / n) * v;
}

SceneFacts::SceneFacts(const scene::SceneSpec& spec, const RollingModel& model, std::vector<Fact> facts)
    : model_(model), facts_(std::move(facts)) {
  const double budget = spin::integratedStepBudget(*model.path, model.ballRadius);
  unwrapOnGrid(spec, budget);
  if (shows(Fact::Delta)) delta = measureDelta(spec);
  if (shows(Fact::Turns)) turns = measureTurns(spec);
  if (shows(Fact::Marks)) marks = measureMarks(spec);
  if (shows(Fact::PhaseSplit)) phaseSplit = measurePhaseSplit(spec, budget);
}

void SceneFacts::unwrapOnGrid(const scene::SceneSpec& spec, double budget) {
  const geometry::ContactPath& path = *model_.path;
  const double L = path.length();
  const spin::Mat3 f0t = startFrameTransposed(path);

  // The unwrapping grid: each step turns the ball and the frame by ≤ 0.05 rad.
  const auto n = static_cast<std::size_t>(std::clamp(std::ceil(budget / 0.05), 2048.0, 400000.0));
  gridS_.resize(n + 1);
  for (std::size_t i = 0; i <= n; ++i) gridS_[i] = i == n ? L : L * double(i) / double(n);
  gridU_ = solveAt(spec, model_, gridS_);
  gridW_.resize(gridS_.size());
  labSum_.assign(gridS_.size(), Vec3::Zero());
  frameSum_ = rollingSum_ = labSum_;
  Su2 w = Su2::identity();
  for (std::size_t i = 0; i < gridS_.size(); ++i) {
    w = frameTurn(path.at(gridS_[i]), f0t, w);
    gridW_[i] = w;
    if (i == 0) continue;
    labSum_[i] = labSum_[i - 1] + incrementRotation(gridU_[i] * gridU_[i - 1].conjugate());
    frameSum_[i] = frameSum_[i - 1] + incrementRotation(gridW_[i] * gridW_[i - 1].conjugate());
    const Su2 v1 = gridW_[i].conjugate() * gridU_[i], v0 = gridW_[i - 1].conjugate() * gridU_[i - 1];
    rollingSum_[i] = rollingSum_[i - 1] + incrementRotation(v1 * v0.conjugate());
  }
  // The revolution axis: the way the frame turns over the path (a circle or a
  // parallel turns about one fixed axis).
  if (frameSum_.back().norm() > 1e-9) revolutionAxis_ = frameSum_.back().normalized();
}

DeltaFact SceneFacts::measureDelta(const scene::SceneSpec& spec) const {
  const double R = model_.ballRadius, turnsOfPath = model_.path->turns();
  const bool onSphere = spec.surface.kind == scene::SurfaceKind::Sphere;
  DeltaFact d;
  d.measured = rollingSum_.back().norm();
  d.onSphere = onSphere;
  d.closedForm = turnsOfPath * (onSphere ? closed_form::sphereParallelDelta(spec.surface.number("radius"),
                                                                            spec.path.colatitudeDeg * kPi / 180.0, R)
                                         : closed_form::planeCircleDelta(planeCircleRadius(model_), R));
  d.labAngle = spin::rotationAngleAxis(gridU_.back()).angle;
  d.closedFormMod = std::abs(wrapAngle(d.closedForm));
  d.wholeCircuits = std::abs(turnsOfPath - std::round(turnsOfPath)) < 1e-9;
  return d;
}

TurnsFact SceneFacts::measureTurns(const scene::SceneSpec& spec) const {
  const double R = model_.ballRadius;
  TurnsFact t{labSum_.back().dot(revolutionAxis_), frameSum_.back().dot(revolutionAxis_)};
  // The paper's penny: one turn inside a sphere of radius 3R.
  const scene::SurfaceSpec& surface = spec.surface;
  t.paperPenny = surface.params.has("side") && surface.params.text("side") == "inside" &&
                 surface.params.has("radius") && std::abs(surface.number("radius") - 3.0 * R) <= 1e-9 * R &&
                 std::abs(model_.path->turns() - 1.0) < 1e-12;
  return t;
}

MarksFact SceneFacts::measureMarks(const scene::SceneSpec& spec) const {
  const geometry::ContactPath& path = *model_.path;
  const double L = path.length();
  MarksFact m;
  m.circleRadius = planeCircleRadius(model_);
  m.beta = closed_form::tennisBallBeta(m.circleRadius, model_.ballRadius);
  const double step = m.beta * m.circleRadius;
  for (int k = 0; k * step <= L * (1.0 + 1e-12); ++k) m.s.push_back(std::min(L, k * step));
  const std::vector<Su2> u = solveAt(spec, model_, m.s);
  const Vec3 n0 = path.at(0.0).normal;
  Su2 previous;
  for (std::size_t k = 0; k < m.s.size(); ++k) {
    const Su2 v = rollingFrame(m.s[k], u[k]);
    if (k > 0) {
      const spin::AngleAxis turn = spin::rotationAngleAxis(v * previous.conjugate());
      m.turn.push_back(turn.angle);
      m.axisFromNormal.push_back(std::acos(std::min(1.0, std::abs(turn.axis.dot(n0)))));
    }
    previous = v;
    m.rolling.push_back(v);
  }
  return m;
}

PhaseSplitFact SceneFacts::measurePhaseSplit(const scene::SceneSpec& spec, double budget) const {
  const geometry::ContactPath& path = *model_.path;
  const double R = model_.ballRadius, L = path.length();
  PhaseSplitFact p;
  // The cyclic spin: an eigenvector of U(L), the one nearer B(0).
  const Su2 uL = gridU_.back();
  const spin::AngleAxis aa = spin::rotationAngleAxis(uL);
  const double psi = spin::spinorAngle(uL);
  const Vec3 b0 = spin::fieldB(path.at(0.0), R).normalized();
  const bool along = aa.axis.dot(b0) >= 0.0;
  const Vec3 x0 = along ? aa.axis : Vec3(-aa.axis);
  // U(L) = cos(ψ/2) − i sin(ψ/2) a·σ: e^{∓iψ/2} on the spin along ±a.
  p.total = wrapAngle(along ? -0.5 * psi : 0.5 * psi);
  p.spinFromField = std::acos(std::clamp(x0.dot(b0), -1.0, 1.0));

  // Quadrature on a grid with ≤ 0.5 rad of turning per panel.
  std::vector<double> nodes, weights;
  gaussNodes(L, std::max(64, int(std::ceil(budget / 0.5))), nodes, weights);
  const std::vector<Su2> u = solveAt(spec, model_, nodes);
  Vec3 meanX = Vec3::Zero(), meanB = Vec3::Zero();
  std::vector<Vec3> xs(nodes.size()), bs(nodes.size()), dxs(nodes.size()), dbs(nodes.size());
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const geometry::DarbouxSample f = path.at(nodes[i]);
    const Vec3 b = spin::fieldB(f, R), omega = -b;
    xs[i] = u[i].rotate(x0);
    dxs[i] = omega.cross(xs[i]);  // dX/ds = ω × X
    bs[i] = b.normalized();
    // Constant curvatures: B is fixed in the Darboux frame, which turns at
    // d = τ_g t − κ_n u + κ_g n, so dB̂/ds = d × B̂.
    const Vec3 d = f.geodesicTorsion * f.tangent - f.normalCurvature * f.tangentNormal + f.geodesicCurvature * f.normal;
    dbs[i] = d.cross(bs[i]);
    p.dynamic += 0.5 * weights[i] * b.dot(xs[i]);
    p.adiabaticDynamic += 0.5 * weights[i] * b.norm();
    meanX += weights[i] * xs[i];
    meanB += weights[i] * bs[i];
  }
  // Both loops are cones about the frame's turning axis (X(s) = W(s) X₀:
  // V(s) turns about X₀'s own axis): measure each about that axis, on the
  // loop's side (either side for a great circle, where the mean vanishes).
  auto coneAxis = [&](const Vec3& mean) {
    return mean.dot(revolutionAxis_) < 0.0 ? Vec3(-revolutionAxis_) : revolutionAxis_;
  };
  const Vec3 cx = coneAxis(meanX), cb = coneAxis(meanB);
  double omegaX = 0.0, omegaB = 0.0;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    omegaX += weights[i] * solidAngleTerm(xs[i], dxs[i], cx);
    omegaB += weights[i] * solidAngleTerm(bs[i], dbs[i], cb);
  }
  p.geometric = -0.5 * omegaX;
  p.berryGeometric = -0.5 * omegaB;
  p.residual = wrapAngle(p.total - p.dynamic - p.geometric);
  p.coneAngle = std::acos(std::clamp(bs.front().dot(cb), -1.0, 1.0));
  p.berryClosedForm =
      -0.5 * std::copysign(2.0 * kPi * std::round(model_.path->turns()) * (1.0 - std::cos(p.coneAngle)), omegaB);
  const int loop = 240;
  for (int k = 0; k <= loop; ++k) p.fieldLoop.push_back(spin::fieldB(path.at(L * k / loop), R).normalized());
  return p;
}

bool SceneFacts::shows(Fact f) const { return std::find(facts_.begin(), facts_.end(), f) != facts_.end(); }

Su2 SceneFacts::frameSpinorNear(double s, const Su2& near) const {
  return frameTurn(model_.path->at(s), startFrameTransposed(*model_.path), near);
}

Su2 SceneFacts::rollingFrame(double s, const Su2& u) const {
  const auto it = std::upper_bound(gridS_.begin(), gridS_.end(), s);
  const std::size_t i = it == gridS_.begin() ? 0 : std::size_t(it - gridS_.begin()) - 1;
  return frameSpinorNear(s, gridW_[i]).conjugate() * u;
}

LiveAngles SceneFacts::at(double s, const Su2& u) const {
  const auto it = std::upper_bound(gridS_.begin(), gridS_.end(), s);
  const std::size_t i = it == gridS_.begin() ? 0 : std::size_t(it - gridS_.begin()) - 1;
  const Su2 w = frameSpinorNear(s, gridW_[i]);
  const Vec3 lab = labSum_[i] + incrementRotation(u * gridU_[i].conjugate());
  const Vec3 frame = frameSum_[i] + incrementRotation(w * gridW_[i].conjugate());
  const Su2 v = w.conjugate() * u, vi = gridW_[i].conjugate() * gridU_[i];
  const Vec3 rolling = rollingSum_[i] + incrementRotation(v * vi.conjugate());
  LiveAngles out;
  out.rolling = rolling.norm();
  if (turns) {
    out.lab = lab.dot(revolutionAxis_);
    out.frame = frame.dot(revolutionAxis_);
  }
  return out;
}

int SceneFacts::marksPassed(double s) const {
  if (!marks) return 0;
  return int(std::upper_bound(marks->s.begin(), marks->s.end(), s * (1.0 + 1e-12)) - marks->s.begin());
}

std::shared_ptr<const SceneFacts> makeSceneFacts(const scene::SceneSpec& spec, const RollingModel& model) {
  // Only what the image shows: the lines need labels and the ball view; the
  // marks are drawn on the path, the cone of B in the twin, labels or not.
  const bool ballView = spec.render.layout != scene::RenderLayout::Twin;
  const bool twinView = spec.render.layout != scene::RenderLayout::Ball;
  std::vector<Fact> facts = scene::resolveFacts(spec);
  std::erase_if(facts, [&](Fact f) {
    return !((spec.render.labels && ballView) || (f == Fact::Marks && ballView) || (f == Fact::PhaseSplit && twinView));
  });
  if (facts.empty()) return nullptr;
  StageLog::instance().record("facts");
  return std::make_shared<const SceneFacts>(spec, model, std::move(facts));
}

}  // namespace rollspin::motion
