// Expression: muparser's bytecode re-evaluated over Jets gives f, ∇f, ∇²f
// with round-off error only. Bound tested: every value and derivative
// within 4e-15 · (1 + |exact|) of its closed form at scattered points.
#include <gtest/gtest.h>

#include <cmath>

#include "geometry/expression.hpp"

using namespace rollspin::geometry;

namespace {

struct Exact {
  double f, fx, fy, fxx, fxy, fyy;
};

void expectJet(const Expression& e, double x, double y, const Exact& want) {
  const Jet j = e.jet(Jet::variableA(x), Jet::variableB(y));
  const double tol = 4e-15;
  EXPECT_NEAR(j.v, want.f, tol * (1 + std::abs(want.f))) << e.text() << " at " << x << "," << y;
  EXPECT_NEAR(j.da, want.fx, tol * (1 + std::abs(want.fx))) << e.text();
  EXPECT_NEAR(j.db, want.fy, tol * (1 + std::abs(want.fy))) << e.text();
  EXPECT_NEAR(j.daa, want.fxx, tol * (1 + std::abs(want.fxx))) << e.text();
  EXPECT_NEAR(j.dab, want.fxy, tol * (1 + std::abs(want.fxy))) << e.text();
  EXPECT_NEAR(j.dbb, want.fyy, tol * (1 + std::abs(want.fyy))) << e.text();
  EXPECT_NEAR(e.value(x, y), want.f, tol * (1 + std::abs(want.f)));
}

const double kPoints[][2] = {{0.3, -0.7}, {1.9, 0.4}, {-2.2, 1.3}, {0.05, 2.5}};

TEST(Expression, ProductOfSines) {
  const Expression e("0.3*sin(x)*cos(y)", {"x", "y"});
  for (auto& p : kPoints) {
    const double x = p[0], y = p[1], s = std::sin(x), c = std::cos(x), sy = std::sin(y), cy = std::cos(y);
    expectJet(e, x, y, {0.3 * s * cy, 0.3 * c * cy, -0.3 * s * sy, -0.3 * s * cy, -0.3 * c * sy, -0.3 * s * cy});
  }
}

TEST(Expression, QuotientExpAndPower) {
  const Expression e("x^3*exp(-y)/(1+x*x)", {"x", "y"});
  for (auto& p : kPoints) {
    const double x = p[0], y = p[1], E = std::exp(-y), d = 1 + x * x;
    const double g = x * x * x / d;                                   // f = g e^{-y}
    const double gx = (3 * x * x * d - 2 * x * x * x * x) / (d * d);  // = (x⁴ + 3x²)/d²
    const double gxx = ((4 * x * x * x + 6 * x) * d - (x * x * x * x + 3 * x * x) * 4 * x) / (d * d * d);
    expectJet(e, x, y, {g * E, gx * E, -g * E, gxx * E, -gx * E, g * E});
  }
}

TEST(Expression, RootsAtan2AndUnaryMinus) {
  const Expression e("-sqrt(x*x+y*y+1) + atan2(y, x)", {"x", "y"});
  for (auto& p : kPoints) {
    const double x = p[0], y = p[1], r2 = x * x + y * y, q = std::sqrt(r2 + 1);
    const double f = -q + std::atan2(y, x);
    const double fx = -x / q - y / r2, fy = -y / q + x / r2;
    const double fxx = -(1 + y * y) / (q * q * q) + 2 * x * y / (r2 * r2);
    const double fxy = x * y / (q * q * q) + (y * y - x * x) / (r2 * r2);
    const double fyy = -(1 + x * x) / (q * q * q) - 2 * x * y / (r2 * r2);
    expectJet(e, x, y, {f, fx, fy, fxx, fxy, fyy});
  }
}

TEST(Expression, ConditionalPicksTheBranchAndItsDerivatives) {
  const Expression e("x < 0 ? -x^2 : x^2*y", {"x", "y"});
  expectJet(e, -1.5, 2.0, {-2.25, 3.0, 0.0, -2.0, 0.0, 0.0});
  expectJet(e, 1.5, 2.0, {4.5, 6.0, 2.25, 4.0, 3.0, 0.0});
}

TEST(Expression, OneVariableCurves) {
  const Expression e("2*cos(t)+0.5*cos(3*t)", {"t"});
  const double t = 0.7;
  const Jet j = e.jet(Jet::variableA(t));
  EXPECT_NEAR(j.v, 2 * std::cos(t) + 0.5 * std::cos(3 * t), 1e-15);
  EXPECT_NEAR(j.da, -2 * std::sin(t) - 1.5 * std::sin(3 * t), 1e-14);
  EXPECT_NEAR(j.daa, -2 * std::cos(t) - 4.5 * std::cos(3 * t), 1e-14);
}

TEST(Expression, ParseErrorsGiveThePosition) {
  struct Bad {
    const char* text;
    int position;
  };
  for (const Bad& b : {Bad{"x+*2", 2}, Bad{"foo(x)", 0}, Bad{"x + z", 4}, Bad{"0.3*sin(x", 9}}) {
    try {
      const Expression e(b.text, {"x", "y"});
      ADD_FAILURE() << b.text << " parsed";
    } catch (const ExpressionError& err) {
      EXPECT_NEAR(err.position(), b.position, 1) << b.text << ": " << err.what();
    }
  }
}

}  // namespace
