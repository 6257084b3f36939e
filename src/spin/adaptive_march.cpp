#include "spin/adaptive_march.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "spin/field.hpp"
#include "spin/frame_propagator.hpp"

namespace rollspin::spin {

namespace {

// Dormand–Prince 5(4) tableau (Hairer, Nørsett & Wanner, Table 5.2).
constexpr std::array<double, 7> kC{0.0, 1.0 / 5, 3.0 / 10, 4.0 / 5, 8.0 / 9, 1.0, 1.0};
constexpr double kA[7][6] = {
    {},
    {1.0 / 5},
    {3.0 / 40, 9.0 / 40},
    {44.0 / 45, -56.0 / 15, 32.0 / 9},
    {19372.0 / 6561, -25360.0 / 2187, 64448.0 / 6561, -212.0 / 729},
    {9017.0 / 3168, -355.0 / 33, 46732.0 / 5247, 49.0 / 176, -5103.0 / 18656},
    {35.0 / 384, 0.0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84},
};
// b₅ − b₄ (the error weights).
constexpr std::array<double, 7> kE{71.0 / 57600,      0.0,        -71.0 / 16695, 71.0 / 1920,
                                   -17253.0 / 339200, 22.0 / 525, -1.0 / 40};
constexpr double kGaussOffset = 0.38729833462074168852;  // √15/10
constexpr double kMaxFrameTurn = 2.5;                    // rad per step, < π

struct Quat {
  double v[4];
};
Quat toQuat(const Su2& u) { return {{u.w, u.x, u.y, u.z}}; }
Su2 toSu2(const Quat& q) { return {q.v[0], q.v[1], q.v[2], q.v[3]}; }
// dU/ds = ½ (0, ω) ⊗ U (the raw spinor equation in quaternion form).
Quat derivative(const Vec3& w, const Quat& q) {
  const Su2 half{0.0, 0.5 * w.x(), 0.5 * w.y(), 0.5 * w.z()};
  return toQuat(half * toSu2(q));
}

struct DpResult {
  Quat y5;
  double error = 0.0;  // scaled RMS error (≤ 1 accept)
};

// One Dormand–Prince step; tol = 0: no estimate.
template <typename Omega>
DpResult dormandPrince(const Omega& omega, const Su2& u, double s, double h, double tol) {
  const Quat y0 = toQuat(u);
  Quat k[7];
  Vec3 w[6];
  for (int i = 0; i < 6; ++i) w[i] = omega(s + kC[i] * h);
  for (int i = 0; i < 7; ++i) {
    Quat y = y0;
    for (int j = 0; j < i; ++j)
      for (int c = 0; c < 4; ++c) y.v[c] += h * kA[i][j] * k[j].v[c];
    if (i == 6) {
      DpResult r{y, 0.0};
      if (tol <= 0.0) return r;
      k[6] = derivative(w[5], y);  // c₇ = 1: the node of stage 6
      double sum = 0.0;
      for (int c = 0; c < 4; ++c) {
        double e = 0.0;
        for (int j = 0; j < 7; ++j) e += kE[j] * k[j].v[c];
        const double scale = tol + tol * std::max(std::abs(y0.v[c]), std::abs(y.v[c]));
        sum += (h * e / scale) * (h * e / scale);
      }
      r.error = std::sqrt(sum / 4.0);
      return r;
    }
    k[i] = derivative(w[i], y);
  }
  return {};
}

// The frame6 element Φ(b) exp(Ω_g) Φ(a)† on [a, b], given the frames at the
// ends (their spinors), κ_g at the three Gauss nodes and the Darboux vector
// at the middle one. The frame's own turn D = Φ(b) Φ(a)† is known up to
// sign; the lift is the sign nearer exp(h d_mid) (as in frame4Element):
// exact for constant curvatures at any h, and right while that estimate is
// within π of the truth (the step cap below keeps it so on varying paths).
struct GaussData {
  double kappaG[3];
  Vec3 darbouxMid = Vec3::Zero();
  double turnRate = 0.0;  // max |d| at the nodes
};
Su2 frame6Element(const Su2& phiA, const Su2& phiB, const GaussData& gd, double ballRadius, double h) {
  const Vec3 g[3] = {{0.0, 1.0 / ballRadius, -gd.kappaG[0]},
                     {0.0, 1.0 / ballRadius, -gd.kappaG[1]},
                     {0.0, 1.0 / ballRadius, -gd.kappaG[2]}};
  Su2 turn = phiB * phiA.conjugate();
  const Su2 predicted = expRotation(h * gd.darbouxMid);
  if (turn.w * predicted.w + turn.x * predicted.x + turn.y * predicted.y + turn.z * predicted.z < 0.0) turn = -turn;
  return turn * (phiA * expRotation(magnus6Exponent(h, g)) * phiA.conjugate());
}

// κ_g and |d| at the Gauss nodes of [s, s + h], d at the middle one.
GaussData gaussData(const geometry::ContactPath& path, double s, double h) {
  const double c[3] = {0.5 - kGaussOffset, 0.5, 0.5 + kGaussOffset};
  GaussData gd;
  for (int i = 0; i < 3; ++i) {
    const geometry::DarbouxSample f = path.at(s + c[i] * h);
    gd.kappaG[i] = f.geodesicCurvature;
    const Vec3 d = geometry::darbouxVector(f);
    if (i == 1) gd.darbouxMid = d;
    gd.turnRate = std::max(gd.turnRate, d.norm());
  }
  return gd;
}

// s as hi + lo (Neumaier): exact enough that 1e9 steps do not drift it.
struct ArcLength {
  double hi = 0.0, lo = 0.0;
  void add(double x) {
    const double t = hi + x;
    lo += std::abs(hi) >= std::abs(x) ? (hi - t) + x : (x - t) + hi;
    hi = t;
  }
  [[nodiscard]] double value() const { return hi + lo; }
};

// One attempted step: the controller's verdict and its factor for the next h.
struct StepAttempt {
  Su2 candidate;  // U at the step's end; when nonFinite, the spinor to report
  Su2 phiEnd;     // frame6a: the frame at the step's end (the next step's start)
  double factor = 1.0;
  bool accept = false;
  bool nonFinite = false;
};

// rk45: Dormand–Prince's embedded estimate against the tolerance.
template <typename Omega>
StepAttempt attemptDormandPrince(const Omega& omega, const Su2& u, double here, double step, double tolerance) {
  StepAttempt t;
  const DpResult r = dormandPrince(omega, u, here, step, tolerance);
  t.candidate = toSu2(r.y5);
  if (!std::isfinite(r.error)) {
    t.nonFinite = true;
    return t;
  }
  t.accept = r.error <= 1.0;
  t.factor = r.error > 0.0 ? std::clamp(0.9 * std::pow(r.error, -0.2), 0.2, 5.0) : 5.0;
  return t;
}

// frame6a: the whole step against its two halves (Richardson), the step
// also capped so the frame turns by at most maxFrameTurn. end: the step's
// end (the breakpoint itself on the segment's last step).
StepAttempt attemptFrame6a(const geometry::ContactPath& path, double ballRadius, const Su2& u, const Su2& phiStart,
                           double here, double step, double end, double tolerance, double length, double maxFrameTurn) {
  StepAttempt t;
  const double half = 0.5 * step;
  const GaussData full = gaussData(path, here, step), left = gaussData(path, here, half),
                  right = gaussData(path, here + half, step - half);
  const double turnRate = std::max({full.turnRate, left.turnRate, right.turnRate});
  const Su2 phiMid = frameSpinor(path.at(here + half));
  t.phiEnd = frameSpinor(path.at(end));
  const Su2 whole = frame6Element(phiStart, t.phiEnd, full, ballRadius, step);
  const Su2 halves = frame6Element(phiMid, t.phiEnd, right, ballRadius, step - half) *
                     frame6Element(phiStart, phiMid, left, ballRadius, half);
  // Richardson: the two halves are 2⁶ times more accurate than the whole.
  const double error = spinorDistance(whole, halves) / 63.0;
  if (!std::isfinite(error) || !halves.isFinite()) {
    t.nonFinite = true;
    t.candidate = u;
    return t;
  }
  // Never ask a step for less than round-off: a tolerance below what
  // double precision can reach degrades to the floor instead of
  // shrinking h until it underflows.
  const double ratio = error / std::max(tolerance * step / length, 8.0 * 2.220446049250313e-16);
  t.factor = ratio > 0.0 ? std::clamp(0.9 * std::pow(ratio, -1.0 / 6.0), 0.2, 4.0) : 4.0;
  t.accept = ratio <= 1.0;
  if (turnRate * step > maxFrameTurn) {
    t.accept = false;
    t.factor = std::min(t.factor, 0.9 * maxFrameTurn / (turnRate * step));
  } else if (turnRate > 0.0) {
    t.factor = std::min(t.factor, maxFrameTurn / (turnRate * step));
  }
  if (t.accept) {
    t.candidate = halves * u;
    const double norm = t.candidate.norm();  // unit elements: project round-off in the norm away
    t.candidate = {t.candidate.w / norm, t.candidate.x / norm, t.candidate.y / norm, t.candidate.z / norm};
  }
  return t;
}

// The march restarts at each breakpoint: [0, b₁, …, L].
std::vector<double> segmentCuts(const geometry::ContactPath& path, double length) {
  std::vector<double> cuts{0.0};
  for (double b : path.breakpoints())
    if (b > 0.0 && b < length) cuts.push_back(b);
  cuts.push_back(length);
  return cuts;
}

}  // namespace

Su2 adaptiveStep(const geometry::ContactPath& path, double ballRadius, Method method, const Su2& u, double s,
                 double h) {
  if (method == Method::Rk45) {
    auto omega = [&](double x) { return angularVelocity(path.at(x), ballRadius); };
    return toSu2(dormandPrince(omega, u, s, h, 0.0).y5);
  }
  return frame6Element(frameSpinor(path.at(s)), frameSpinor(path.at(s + h)), gaussData(path, s, h), ballRadius, h) * u;
}

SolveStats adaptiveRun(const geometry::ContactPath& path, double ballRadius, Method method, double tolerance,
                       long long stepLimit, const SampleArcLengths& sampleS, const SampleSink& sink) {
  SolveStats stats;
  stats.method = method;
  const double length = path.length();
  auto track = [&stats](const Su2& u) {
    stats.unitarityError = std::max(stats.unitarityError, std::abs(u.norm() - 1.0));
    return u.isFinite();
  };
  auto stop = [&stats](SolveStatus status, const Su2& u) {
    stats.status = status;
    stats.final = u;
    return stats;
  };
  auto omega = [&](double x) { return angularVelocity(path.at(x), ballRadius); };
  // On constant curvatures frame6a is exact at any h and the lift exact too:
  // no cap, so 1e6 lollipop turns take a dozen steps.
  const double maxFrameTurn = path.hasConstantCurvatures() ? INFINITY : kMaxFrameTurn;

  const std::vector<double> cuts = segmentCuts(path, length);

  Su2 u = Su2::identity();
  std::size_t next = 0;
  double h = 0.0;

  for (std::size_t seg = 0; seg + 1 < cuts.size(); ++seg) {
    const double a = cuts[seg], b = cuts[seg + 1];
    ArcLength s;
    s.hi = a;
    // frame6a reuses the frame at the step's start from the previous step's end.
    Su2 phiStart = method == Method::Frame6a ? frameSpinor(path.at(a)) : Su2{};
    if (h <= 0.0) {
      // First guess: half a radian of rotation or of frame turn; the
      // controller corrects it within a few attempts.
      const geometry::DarbouxSample f = path.at(a);
      const double rate = angularVelocity(f, ballRadius).norm() + geometry::darbouxVector(f).norm();
      h = rate > 0.0 ? 0.5 / rate : (b - a);
    }
    while (b - s.value() > 0.0) {
      if (stats.steps + stats.rejectedSteps >= stepLimit) return stop(SolveStatus::StepLimit, u);
      const double here = s.value();
      // Land on the breakpoint: stretch a step that would leave a sliver.
      const bool last = h >= 0.999 * (b - here);
      const double step = last ? b - here : h;
      if (!(step > 1e-14 * std::max(1.0, std::abs(b)))) return stop(SolveStatus::StepSizeUnderflow, u);

      const double end = last ? b : here + step;
      const StepAttempt attempt = method == Method::Rk45 ? attemptDormandPrince(omega, u, here, step, tolerance)
                                                         : attemptFrame6a(path, ballRadius, u, phiStart, here, step,
                                                                          end, tolerance, length, maxFrameTurn);
      if (attempt.nonFinite) return stop(SolveStatus::NonFinite, attempt.candidate);
      const double factor = attempt.factor;

      if (!attempt.accept) {
        ++stats.rejectedSteps;
        h = step * std::min(factor, 1.0);
        continue;
      }
      // Samples inside [here, here + step): a partial step from this node.
      while (next < sampleS.size() && !sampleS.beyondSlice(next) && sampleS[next] < end) {
        const double dh = (sampleS[next] - s.hi) - s.lo;
        const Su2 uj = dh <= 0.0 ? u : adaptiveStep(path, ballRadius, method, u, here, dh);
        if (!track(uj)) return stop(SolveStatus::NonFinite, uj);
        if (sink) sink(next, sampleS[next], uj);
        ++next;
      }
      u = attempt.candidate;
      phiStart = attempt.phiEnd;
      ++stats.steps;
      if (!track(u)) return stop(SolveStatus::NonFinite, u);
      if (last) {
        s.hi = b;
        s.lo = 0.0;
      } else {
        s.add(step);
      }
      // After a step cut to the breakpoint keep the controller's h, not the sliver.
      h = (last ? std::max(h, step) : step) * factor;
    }
  }
  for (; next < sampleS.size() && !sampleS.beyondSlice(next); ++next)
    if (sink) sink(next, sampleS[next], u);
  stats.final = u;
  stats.samplesReported = next;
  stats.status = SolveStatus::Ok;
  return stats;
}

}  // namespace rollspin::spin
