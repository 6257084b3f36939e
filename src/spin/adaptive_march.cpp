#include "spin/adaptive_march.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "spin/field.hpp"

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
constexpr std::array<double, 7> kE{71.0 / 57600,      0.0,          -71.0 / 16695, 71.0 / 1920,
                                   -17253.0 / 339200, 22.0 / 525,  -1.0 / 40};
constexpr double kGaussOffset = 0.38729833462074168852;  // √15/10

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

// One Dormand–Prince step; ω(s + c_i h) from `omega`. tol = 0: no estimate.
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
      k[6] = derivative(w[5], y);  // c₇ = 1: same node as stage 6 (FSAL)
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

}  // namespace

Su2 adaptiveStep(const geometry::ContactPath& path, double ballRadius, Method method, const Su2& u, double s,
                 double h) {
  auto omega = [&](double x) { return angularVelocity(path.at(x), ballRadius); };
  if (method == Method::Rk45) return toSu2(dormandPrince(omega, u, s, h, 0.0).y5);
  const Vec3 w[3] = {omega(s + (0.5 - kGaussOffset) * h), omega(s + 0.5 * h), omega(s + (0.5 + kGaussOffset) * h)};
  return expRotation(magnus6Exponent(h, w)) * u;
}

SolveStats adaptiveRun(const geometry::ContactPath& path, double ballRadius, Method method, double tolerance,
                       std::span<const double> sampleS, const SampleSink& sink) {
  SolveStats stats;
  stats.method = method;
  const double length = path.length();
  auto track = [&stats](const Su2& u) {
    stats.unitarityError = std::max(stats.unitarityError, std::abs(u.norm() - 1.0));
    return u.isFinite();
  };
  auto omega = [&](double x) { return angularVelocity(path.at(x), ballRadius); };

  std::vector<double> cuts{0.0};
  for (double b : path.breakpoints())
    if (b > 0.0 && b < length) cuts.push_back(b);
  cuts.push_back(length);

  // A runaway march (tolerance far below round-off, or a field that keeps
  // the step tiny) stops with a status instead of running for hours.
  constexpr long long kMaxAttempts = 2'000'000'000;
  Su2 u = Su2::identity();
  std::size_t next = 0;
  double h = 0.0;

  for (std::size_t seg = 0; seg + 1 < cuts.size(); ++seg) {
    const double a = cuts[seg], b = cuts[seg + 1];
    double s = a;
    if (h <= 0.0) {
      // First guess: half a radian of rotation or of frame turn; the
      // controller corrects it within a few attempts.
      const geometry::DarbouxSample f = path.at(a);
      const double rate = angularVelocity(f, ballRadius).norm() + geometry::darbouxVector(f).norm();
      h = rate > 0.0 ? 0.5 / rate : (b - a);
    }
    while (s < b) {
      if (stats.steps + stats.rejectedSteps >= kMaxAttempts) {
        stats.status = SolveStatus::StepSizeUnderflow;
        stats.final = u;
        return stats;
      }
      // Land on the breakpoint: stretch a step that would leave a sliver.
      const bool last = h >= 0.999 * (b - s);
      const double step = last ? b - s : h;
      if (!(step > 1e-14 * std::max(1.0, std::abs(b)))) {
        stats.status = SolveStatus::StepSizeUnderflow;
        stats.final = u;
        return stats;
      }

      Su2 candidate;
      double factor = 1.0;
      bool accept = false;
      if (method == Method::Rk45) {
        const DpResult r = dormandPrince(omega, u, s, step, tolerance);
        if (!std::isfinite(r.error)) {
          stats.status = SolveStatus::NonFinite;
          stats.final = toSu2(r.y5);
          return stats;
        }
        candidate = toSu2(r.y5);
        accept = r.error <= 1.0;
        factor = r.error > 0.0 ? 0.9 * std::pow(r.error, -0.2) : 5.0;
        factor = std::clamp(factor, 0.2, 5.0);
      } else {
        Vec3 w[3];
        double turnRate = 0.0;
        const double c[3] = {0.5 - kGaussOffset, 0.5, 0.5 + kGaussOffset};
        for (int i = 0; i < 3; ++i) {
          const geometry::DarbouxSample f = path.at(s + c[i] * step);
          w[i] = angularVelocity(f, ballRadius);
          turnRate = std::max(turnRate, geometry::darbouxVector(f).norm());
        }
        Vec3 fourth;
        const Vec3 sixth = magnus6Exponent(step, w, &fourth);
        const double estimate = (sixth - fourth).norm();
        if (!std::isfinite(estimate) || !sixth.allFinite()) {
          stats.status = SolveStatus::NonFinite;
          stats.final = u;
          return stats;
        }
        const double allowed = tolerance * step / length;
        const double ratio = estimate / allowed;
        factor = ratio > 0.0 ? std::clamp(0.9 * std::pow(ratio, -0.25), 0.2, 4.0) : 4.0;
        accept = ratio <= 1.0;
        if (turnRate * step > 1.0) {
          accept = false;
          factor = std::min(factor, 0.9 / (turnRate * step));
        } else if (turnRate > 0.0) {
          factor = std::min(factor, 1.0 / (turnRate * step));
        }
        if (accept) {
          candidate = expRotation(sixth) * u;
          const double norm = candidate.norm();  // unit elements: project round-off in the norm away
          candidate = {candidate.w / norm, candidate.x / norm, candidate.y / norm, candidate.z / norm};
        }
      }

      if (!accept) {
        ++stats.rejectedSteps;
        h = step * std::min(factor, 1.0);
        continue;
      }
      // Samples inside [s, s + step): one partial step from the accepted node.
      const double end = last ? b : s + step;
      while (next < sampleS.size() && sampleS[next] < end) {
        const double dh = sampleS[next] - s;
        const Su2 uj = dh <= 0.0 ? u : adaptiveStep(path, ballRadius, method, u, s, dh);
        if (!track(uj)) {
          stats.status = SolveStatus::NonFinite;
          stats.final = uj;
          return stats;
        }
        if (sink) sink(next, sampleS[next], uj);
        ++next;
      }
      u = candidate;
      ++stats.steps;
      if (!track(u)) {
        stats.status = SolveStatus::NonFinite;
        stats.final = u;
        return stats;
      }
      s = end;
      // After a cut step keep the controller's h, not the sliver.
      h = last ? std::max(h, step) * factor : step * factor;
    }
  }
  for (; next < sampleS.size(); ++next)
    if (sink) sink(next, sampleS[next], u);
  stats.final = u;
  stats.status = SolveStatus::Ok;
  return stats;
}

}  // namespace rollspin::spin
