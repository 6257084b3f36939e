#include "spin/propagator.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>

#include "spin/field.hpp"

namespace rollspin::spin {

namespace {
constexpr std::array kMethods{Method::Exact, Method::Magnus2, Method::Magnus4, Method::Rk4};

// dU/ds = ½ (0, ω) ⊗ U in quaternion form, for the raw-spinor RK4.
Su2 derivative(const Vec3& w, const Su2& u) {
  const Su2 half{0.0, 0.5 * w.x(), 0.5 * w.y(), 0.5 * w.z()};
  return half * u;
}
Su2 axpy(const Su2& u, double h, const Su2& k) { return {u.w + h * k.w, u.x + h * k.x, u.y + h * k.y, u.z + h * k.z}; }
}  // namespace

std::string_view methodName(Method m) {
  switch (m) {
    case Method::Exact: return "exact";
    case Method::Magnus2: return "magnus2";
    case Method::Magnus4: return "magnus4";
    case Method::Rk4: return "rk4";
  }
  return "?";
}

std::optional<Method> parseMethod(std::string_view name) {
  for (Method m : kMethods)
    if (methodName(m) == name) return m;
  return std::nullopt;
}

std::span<const Method> allMethods() { return kMethods; }

int methodOrder(Method m) {
  switch (m) {
    case Method::Exact: return 0;
    case Method::Magnus2: return 2;
    case Method::Magnus4: return 4;
    case Method::Rk4: return 4;
  }
  return 0;
}

std::string_view statusMessage(SolveStatus s) {
  switch (s) {
    case SolveStatus::Ok: return "ok";
    case SolveStatus::NonFinite: return "the solution became NaN or infinite";
    case SolveStatus::ExactNeedsConstantCurvature:
      return "method 'exact' needs a path with constant curvatures (line, circle, parallel)";
    case SolveStatus::BadSteps: return "steps must be at least 1";
  }
  return "?";
}

Propagator::Propagator(const geometry::ContactPath& path, double ballRadius, Method method, long long steps)
    : path_(path), ballRadius_(ballRadius), method_(method), steps_(steps) {
  if (method_ == Method::Exact && path_.hasConstantCurvatures()) {
    const geometry::DarbouxSample f0 = path_.at(0.0);
    d0_ = geometry::darbouxVector(f0);
    e0_ = angularVelocity(f0, ballRadius_) - d0_;
  }
}

Vec3 Propagator::omega(double s) const { return angularVelocity(path_.at(s), ballRadius_); }

Su2 Propagator::closedForm(double s) const { return expRotation(s * d0_) * expRotation(s * e0_); }

Su2 Propagator::step(const Su2& u, double s, double h) const {
  switch (method_) {
    case Method::Exact: return closedForm(s + h);
    case Method::Magnus2: return expRotation(h * omega(s + 0.5 * h)) * u;
    case Method::Magnus4: {
      constexpr double c = 0.28867513459481288225;  // √3/6
      const Vec3 w1 = omega(s + (0.5 - c) * h), w2 = omega(s + (0.5 + c) * h);
      const Vec3 magnus = (0.5 * h) * (w1 + w2) + (0.14433756729740644113 * h * h) * w2.cross(w1);  // √3/12
      return expRotation(magnus) * u;
    }
    case Method::Rk4: {
      const Vec3 wa = omega(s), wb = omega(s + 0.5 * h), wc = omega(s + h);
      const Su2 k1 = derivative(wa, u);
      const Su2 k2 = derivative(wb, axpy(u, 0.5 * h, k1));
      const Su2 k3 = derivative(wb, axpy(u, 0.5 * h, k2));
      const Su2 k4 = derivative(wc, axpy(u, h, k3));
      return {u.w + h / 6.0 * (k1.w + 2 * k2.w + 2 * k3.w + k4.w), u.x + h / 6.0 * (k1.x + 2 * k2.x + 2 * k3.x + k4.x),
              u.y + h / 6.0 * (k1.y + 2 * k2.y + 2 * k3.y + k4.y), u.z + h / 6.0 * (k1.z + 2 * k2.z + 2 * k3.z + k4.z)};
    }
  }
  return u;
}

SolveStats Propagator::run(std::span<const double> sampleS, const SampleSink& sink) const {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  SolveStats stats;
  stats.method = method_;
  const double length = path_.length();
  auto track = [&stats](const Su2& u) {
    stats.unitarityError = std::max(stats.unitarityError, std::abs(u.norm() - 1.0));
    return u.isFinite();
  };
  auto finish = [&](SolveStatus status) {
    stats.status = status;
    stats.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return stats;
  };

  if (method_ == Method::Exact) {
    if (!path_.hasConstantCurvatures()) return finish(SolveStatus::ExactNeedsConstantCurvature);
    for (std::size_t j = 0; j < sampleS.size(); ++j) {
      const Su2 u = closedForm(sampleS[j]);
      if (!track(u)) return finish(SolveStatus::NonFinite);
      if (sink) sink(j, sampleS[j], u);
    }
    stats.final = closedForm(length);
    if (!track(stats.final)) return finish(SolveStatus::NonFinite);
    return finish(SolveStatus::Ok);
  }
  if (steps_ < 1) return finish(SolveStatus::BadSteps);

  // Segment boundaries: 0, breakpoints, L; steps shared by length, ≥ 1 each.
  std::vector<double> cuts{0.0};
  for (double b : path_.breakpoints())
    if (b > 0.0 && b < length) cuts.push_back(b);
  cuts.push_back(length);

  Su2 u = Su2::identity();
  std::size_t next = 0;
  auto emitUpTo = [&](double sNode, const Su2& uNode, double sEnd, double h, bool inclusiveEnd) {
    // Samples in [sNode, sEnd) (or [sNode, sEnd] at the very end): one partial step each.
    while (next < sampleS.size() && (sampleS[next] < sEnd || (inclusiveEnd && sampleS[next] <= sEnd))) {
      const double sj = std::max(sampleS[next], sNode);
      const double dh = sj - sNode;
      const Su2 uj = dh == 0.0 ? uNode : (dh >= h ? step(uNode, sNode, h) : step(uNode, sNode, dh));
      if (!track(uj)) return false;
      if (sink) sink(next, sampleS[next], uj);
      ++next;
    }
    return true;
  };

  for (std::size_t seg = 0; seg + 1 < cuts.size(); ++seg) {
    const double a = cuts[seg], b = cuts[seg + 1];
    const long long n =
        std::max<long long>(1, std::llround(static_cast<double>(steps_) * (b - a) / std::max(length, 1e-300)));
    const double h = (b - a) / static_cast<double>(n);
    for (long long k = 0; k < n; ++k) {
      const double s = a + static_cast<double>(k) * h;
      const bool lastStep = (seg + 2 == cuts.size()) && (k + 1 == n);
      const double sNext = (k + 1 == n) ? b : s + h;
      if (!emitUpTo(s, u, sNext, h, false)) return finish(SolveStatus::NonFinite);
      u = step(u, s, sNext - s);
      ++stats.steps;
      if (!track(u)) return finish(SolveStatus::NonFinite);
      if (lastStep && !emitUpTo(sNext, u, sNext, h, true)) return finish(SolveStatus::NonFinite);
    }
  }
  stats.final = u;
  return finish(SolveStatus::Ok);
}

std::vector<double> uniformSamples(double length, std::size_t count) {
  std::vector<double> s(std::max<std::size_t>(count, 2));
  const double n = static_cast<double>(s.size() - 1);
  for (std::size_t j = 0; j < s.size(); ++j) s[j] = length * static_cast<double>(j) / n;
  s.back() = length;
  return s;
}

}  // namespace rollspin::spin
