#include "spin/field.hpp"

#include <algorithm>
#include <cmath>

namespace rollspin::spin {

double integratedFieldStrength(const geometry::ContactPath& path, double ballRadius) {
  // 5-point Gauss–Legendre on 64 panels per breakpoint segment: |B| is smooth
  // within a segment, and this is only used for heuristics and the floor.
  static constexpr double x[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831,
                                  0.9061798459386640};
  static constexpr double wts[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                                    0.4786286704993665, 0.2369268850561891};
  std::vector<double> cuts{0.0};
  for (double b : path.breakpoints()) cuts.push_back(b);
  cuts.push_back(path.length());
  double total = 0.0;
  for (std::size_t seg = 0; seg + 1 < cuts.size(); ++seg) {
    const int panels = 64;
    const double a = cuts[seg], h = (cuts[seg + 1] - a) / panels;
    for (int p = 0; p < panels; ++p) {
      const double mid = a + (p + 0.5) * h;
      for (int k = 0; k < 5; ++k) {
        total += 0.5 * h * wts[k] * angularVelocity(path.at(mid + 0.5 * h * x[k]), ballRadius).norm();
      }
    }
  }
  return total;
}

}  // namespace rollspin::spin
