// Every surface × curve kind: the spinor timeline (magnus4 and frame4)
// against the independent SO(3) integration of the rolling constraint
// (ω = (1/R) n × dC/ds from the surface's own point and normal), ≤ 1e-10 in
// rotation angle at every sample, and the rolling-constraint residuals of
// the spinor's own quaternions (no slip, no spin) ≤ 1e-9.
#include <gtest/gtest.h>

#include <cstdlib>

#include "kinematics/rolling_kinematics.hpp"
#include "surface_support.hpp"

using namespace rollspin;
using namespace rollspin::test;

namespace {

class SurfaceOracle : public ::testing::TestWithParam<SurfaceCase> {};

// RK4 on SO(3) converges as h⁴: 1/3000 of a unit of length (R ≥ 0.6 here)
// puts its own error near 1e-12 on these paths.
long long kinematicSteps(const geometry::ContactPath& path) {
  return std::max<long long>(8000, static_cast<long long>(3000.0 * path.length()));
}

TEST_P(SurfaceOracle, SpinorMatchesKinematics) {
  const SurfaceCase& c = GetParam();
  const auto path = c.make();
  const long long steps = generousSteps(*path, c.R);
  const std::vector<double> s = spin::uniformSamples(path->length(), 41);
  const auto oracle =
      kinematics::RollingKinematics(*path, c.R, {kinematicSteps(*path), oracleDifferenceStep(c.R)}).orientations(s);
  const OracleComparison m4 = compareWithOrientations(*path, c.R, spin::Method::Magnus4, steps, s, oracle);
  const OracleComparison f4 = compareWithOrientations(*path, c.R, spin::Method::Frame4, steps, s, oracle);
  // Constant κ_n, κ_g, τ_g (parallels, helices, great circles, torus
  // meridians): the closed form is an oracle too.
  OracleComparison ex;
  if (path->hasConstantCurvatures()) ex = compareWithOrientations(*path, c.R, spin::Method::Exact, 0, s, oracle);
  if (std::getenv("ROLLSPIN_VERBOSE")) {
    std::printf("%-32s L=%7.3f steps=%6lld magnus4 %.2e frame4 %.2e", c.name.c_str(), path->length(), steps,
                m4.worstGap, f4.worstGap);
    if (path->hasConstantCurvatures()) std::printf(" exact %.2e", ex.worstGap);
    std::printf("\n");
  }
  EXPECT_LE(m4.worstGap, 1e-10) << c.name << ": " << path->describe();
  EXPECT_LE(f4.worstGap, 1e-10) << c.name << ": " << path->describe();
  EXPECT_LE(ex.worstGap, 1e-10) << c.name << ": " << path->describe();
  EXPECT_LE(m4.unitarityError, 1e-13);
  EXPECT_LE(f4.unitarityError, 1e-13);
}

TEST_P(SurfaceOracle, RollingResidualsStaySmall) {
  const SurfaceCase& c = GetParam();
  const auto path = c.make();
  const Residuals r = rollingResiduals(*path, c.R, spin::Method::Magnus4, generousSteps(*path, c.R));
  if (std::getenv("ROLLSPIN_VERBOSE")) std::printf("%-32s slip %.2e spin %.2e\n", c.name.c_str(), r.slip, r.spin);
  EXPECT_LE(r.slip, 1e-9) << c.name;
  EXPECT_LE(r.spin, 1e-9) << c.name;
}

std::string caseName(const ::testing::TestParamInfo<SurfaceCase>& info) {
  std::string n;
  for (char ch : info.param.name) n += std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
  return n;
}

INSTANTIATE_TEST_SUITE_P(AllKinds, SurfaceOracle, ::testing::ValuesIn(allSurfaceCases()), caseName);

}  // namespace
