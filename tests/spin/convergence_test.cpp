// Orders of convergence and unitarity: magnus4 is fourth order, magnus2
// second, both unitary to round-off at any step; rk4 on the raw spinor drifts.
#include <gtest/gtest.h>

#include <cmath>

#include "oracle_support.hpp"
#include "support/test_paths.hpp"

using namespace rollspin;
using namespace rollspin::test;
using spin::Method;

namespace {
// Error against the closed form, on one lollipop circuit (R = 1, r = 3).
double errorAt(Method m, long long steps) {
  const auto path = lollipopPath(3.0);
  const spin::Su2 exact = solveFinal(*path, 1.0, Method::Exact, 0);
  return spin::spinorDistance(solveFinal(*path, 1.0, m, steps), exact);
}

double observedRatio(Method m, long long coarse) { return errorAt(m, coarse) / errorAt(m, 2 * coarse); }
}  // namespace

TEST(Convergence, Magnus4IsFourthOrder) {
  // Error ratio per halved step → 2⁴ = 16 while the error is far above round-off.
  for (long long n : {40, 80, 160}) {
    const double ratio = observedRatio(Method::Magnus4, n);
    EXPECT_GT(ratio, 14.5) << n;
    EXPECT_LT(ratio, 17.5) << n;
  }
}

TEST(Convergence, Magnus2IsSecondOrder) {
  for (long long n : {40, 80, 160}) {
    const double ratio = observedRatio(Method::Magnus2, n);
    EXPECT_GT(ratio, 3.7) << n;
    EXPECT_LT(ratio, 4.3) << n;
  }
}

TEST(Convergence, Rk4IsFourthOrderButNotUnitary) {
  for (long long n : {80, 160}) {
    const double ratio = observedRatio(Method::Rk4, n);
    EXPECT_GT(ratio, 14.0) << n;
    EXPECT_LT(ratio, 18.0) << n;
  }
}

TEST(Convergence, GeometricMethodsStayUnitaryWhereRk4Drifts) {
  // 1000 circuits with h|ω| = 0.1: rk4's amplification factor per step is
  // 1 − O((h|ω|)⁶), which adds up to a visible loss of norm; the Magnus
  // methods multiply exact SU(2) elements.
  const auto path = lollipopPath(3.0, 1000.0);
  const long long steps = static_cast<long long>(path->length() / 0.1);
  const auto rk4 = spin::Propagator(*path, 1.0, Method::Rk4, steps).solveFinal();
  const auto m4 = spin::Propagator(*path, 1.0, Method::Magnus4, steps).solveFinal();
  const auto m2 = spin::Propagator(*path, 1.0, Method::Magnus2, steps).solveFinal();
  EXPECT_GT(rk4.unitarityError, 1e-5);  // measured: 2e-5
  EXPECT_LT(m4.unitarityError, 1e-13);
  EXPECT_LT(m2.unitarityError, 1e-13);
}

TEST(Convergence, ExactIsRoundOffAtAnyArcLength) {
  // The closed form evaluated at s against magnus4 with a fine grid, at
  // arbitrary s (not grid nodes).
  const auto path = lollipopPath(3.0, 2.0);
  const std::vector<double> s{0.0, 0.123, 3.3, 9.99, 20.5, path->length()};
  std::vector<spin::Su2> exact(s.size()), fine(s.size());
  (void)spin::Propagator(*path, 1.0, Method::Exact, 0).run(s, [&](std::size_t j, double, const spin::Su2& q) {
    exact[j] = q;
  });
  (void)spin::Propagator(*path, 1.0, Method::Magnus4, 40000).run(s, [&](std::size_t j, double, const spin::Su2& q) {
    fine[j] = q;
  });
  for (std::size_t j = 0; j < s.size(); ++j) EXPECT_LT(spin::spinorDistance(exact[j], fine[j]), 1e-12) << s[j];
}
