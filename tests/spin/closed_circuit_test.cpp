// Closed circuits on parallels of surfaces of revolution, either side: after
// one turn the ball is rotated by δ = 2π √(ρ²/R² + cos²β) (ρ the parallel's
// radius, β the slope of the meridian against the plane of the parallel)
// about e₀ = u₀/R − κ_g n₀, and the spinor is U(L) = −exp(−(i/2) δ ê₀·σ)
// (the frame's own 2π turn contributes the sign). Derivation: constant κ_n,
// κ_g, τ_g give U(s) = exp(−(i/2) s d·σ) exp(−(i/2) s e·σ) with |d| L = 2π.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>

#include "kinematics/rolling_kinematics.hpp"
#include "support/numbers.hpp"
#include "surface_support.hpp"

using namespace rollspin;
using namespace rollspin::geometry;
using namespace rollspin::test;

namespace {

using rollspin::test::kDeg;
using rollspin::test::kPi;

struct Circuit {
  std::string name;
  std::function<std::unique_ptr<ContactPath>()> make;
  double R, rho, cosBeta;
};

std::vector<Circuit> circuits() {
  std::vector<Circuit> out;
  for (bool outside : {true, false}) {
    const Side side = outside ? Side::Outside : Side::Inside;
    const std::string tag = outside ? " outside" : " inside";
    auto cyl = std::make_shared<const Cylinder>(2.0, Vec3(0, 0, 1), side);
    out.push_back({"cylinder" + tag,
                   [=] { return std::unique_ptr<ContactPath>(cylinderParallel(cyl, 0.3, 1.0, true)); }, 1.5, 2.0, 0.0});
    auto torus = std::make_shared<const Torus>(4.0, 1.5, side);
    for (double psi : {0.0, 50 * kDeg, 120 * kDeg, 180 * kDeg})
      out.push_back({"torus psi=" + std::to_string(int(psi / kDeg)) + tag,
                     [=] { return std::unique_ptr<ContactPath>(torusParallel(torus, psi, 1.0, psi < 1.0)); }, 0.7,
                     4.0 + 1.5 * std::cos(psi), std::abs(std::sin(psi))});
    auto bowl = HeightField::quadric(3.0, 3.0, false, outside);
    for (double rho : {0.8, 2.5})
      out.push_back({"paraboloid rho=" + std::to_string(rho) + tag,
                     [=] { return std::unique_ptr<ContactPath>(heightFieldParallel(bowl, rho, 1.0, true)); }, 1.2, rho,
                     1.0 / std::sqrt(1 + rho * rho / 9.0)});
    auto sphere = std::make_shared<const Sphere>(3.0, side);
    for (double theta : {35 * kDeg, 90 * kDeg, 140 * kDeg})
      out.push_back({"sphere theta=" + std::to_string(int(theta / kDeg)) + tag,
                     [=] { return std::unique_ptr<ContactPath>(sphereParallel(sphere, theta, 1.0, false)); }, 1.0,
                     3.0 * std::sin(theta), std::abs(std::cos(theta))});
  }
  return out;
}

TEST(ClosedCircuit, ParallelsTurnTheBallByTheClosedForm) {
  for (const Circuit& c : circuits()) {
    const auto path = c.make();
    const double delta = 2 * kPi * std::sqrt(c.rho * c.rho / (c.R * c.R) + c.cosBeta * c.cosBeta);
    const DarbouxSample f0 = path->at(0.0);
    const Vec3 e0 = f0.tangentNormal / c.R - f0.geodesicCurvature * f0.normal;
    const spin::Su2 expected = -spin::expRotation(delta * e0.normalized());
    for (auto [method, steps] : {std::pair{spin::Method::Exact, 0LL}, std::pair{spin::Method::Frame4, 8LL},
                                 std::pair{spin::Method::Magnus4, 6000LL}}) {
      const spin::SolveStats st = spin::Propagator(*path, c.R, method, steps).solveFinal();
      ASSERT_EQ(st.status, spin::SolveStatus::Ok) << c.name;
      if (std::getenv("ROLLSPIN_VERBOSE"))
        std::printf("%-26s %-8s δ = %8.4f  |U − U_closed| = %.1e\n", c.name.c_str(),
                    std::string(spin::methodName(method)).c_str(), delta, spin::spinorDistance(st.final, expected));
      EXPECT_LE(spin::spinorDistance(st.final, expected), 1e-10)
          << c.name << " method " << spin::methodName(method) << " δ = " << delta;
    }
  }
}

TEST(ClosedCircuit, KinematicsAgreeWithTheClosedFormOnBothSides) {
  for (const Circuit& c : circuits()) {
    if (c.name.rfind("torus psi=50", 0) != 0 && c.name.rfind("paraboloid rho=2", 0) != 0) continue;
    const auto path = c.make();
    const double delta = 2 * kPi * std::sqrt(c.rho * c.rho / (c.R * c.R) + c.cosBeta * c.cosBeta);
    const Eigen::Matrix3d q =
        kinematics::RollingKinematics(*path, c.R, {static_cast<long long>(1500 * path->length()), 0.0})
            .finalOrientation();
    const Eigen::AngleAxisd aa(q);
    const double folded = std::abs(std::remainder(delta, 2 * kPi));
    if (std::getenv("ROLLSPIN_VERBOSE"))
      std::printf("%-26s kinematics angle gap %.1e\n", c.name.c_str(), std::abs(aa.angle() - folded));
    EXPECT_NEAR(aa.angle(), folded, 1e-9) << c.name;
  }
}

}  // namespace
