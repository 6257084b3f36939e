#include "spin/field.hpp"

#include <algorithm>
#include <cmath>

namespace rollspin::spin {

namespace {
// ∫₀ᴸ f(frame at s) ds: 5-point Gauss–Legendre on 64 panels per breakpoint
// segment (f is smooth inside a segment; used for heuristics and the floor).
template <typename F>
std::vector<double> integratePerSegment(const geometry::ContactPath& path, F&& f) {
  static constexpr double x[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831,
                                  0.9061798459386640};
  static constexpr double wts[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
                                    0.2369268850561891};
  std::vector<double> cuts{0.0};
  for (double b : path.breakpoints())
    if (b > 0.0 && b < path.length()) cuts.push_back(b);  // as the steppers cut it
  cuts.push_back(path.length());
  std::vector<double> perSegment;
  for (std::size_t seg = 0; seg + 1 < cuts.size(); ++seg) {
    double total = 0.0;
    const int panels = 64;
    const double a = cuts[seg], h = (cuts[seg + 1] - a) / panels;
    for (int p = 0; p < panels; ++p) {
      const double mid = a + (p + 0.5) * h;
      for (int k = 0; k < 5; ++k) total += 0.5 * h * wts[k] * f(path.at(mid + 0.5 * h * x[k]));
    }
    perSegment.push_back(total);
  }
  return perSegment;
}
template <typename F>
double integrateAlong(const geometry::ContactPath& path, F&& f) {
  double total = 0.0;
  for (double part : integratePerSegment(path, f)) total += part;
  return total;
}
double stepRate(const geometry::DarbouxSample& f, double ballRadius) {
  return angularVelocity(f, ballRadius).norm() + geometry::darbouxVector(f).norm();
}
}  // namespace

double integratedFieldStrength(const geometry::ContactPath& path, double ballRadius) {
  return integrateAlong(path, [&](const geometry::DarbouxSample& f) { return angularVelocity(f, ballRadius).norm(); });
}

double integratedStepBudget(const geometry::ContactPath& path, double ballRadius) {
  return integrateAlong(path, [&](const geometry::DarbouxSample& f) { return stepRate(f, ballRadius); });
}

std::vector<double> segmentStepBudgets(const geometry::ContactPath& path, double ballRadius) {
  return integratePerSegment(path, [&](const geometry::DarbouxSample& f) { return stepRate(f, ballRadius); });
}

}  // namespace rollspin::spin
