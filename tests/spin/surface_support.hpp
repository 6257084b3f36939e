// Shared by the spin suites on curved surfaces: the spinor-versus-kinematics
// comparison and the rolling-constraint residuals (the surface × curve cases
// are support/surface_cases.hpp).
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <functional>
#include <memory>
#include <numeric>
#include <string>
#include <vector>

#include "geometry/surface_paths.hpp"
#include "kinematics/rolling_kinematics.hpp"
#include "spin/propagator.hpp"
#include "spin/su2.hpp"
#include "support/surface_cases.hpp"

namespace rollspin::test {

// The oracle's finite-difference spacing for dC/ds. Its automatic choice,
// 1e-2 min(R, segment/8), ignores the path's own curvature: on a curve with
// κ_g = 6 (plane uv case) it is off by 6e-9; 2e-3 min(1, R) resolves every
// curve here (its round-off, ε|C|/h, stays below 1e-12).
double oracleDifferenceStep(double R);

// Rotation angle between R(U) and Q (SO(3) distance, atan2-based).
double rotationGap(const spin::Su2& u, const Eigen::Matrix3d& q);

struct OracleComparison {
  double worstGap = 0.0;  // max over samples of the SO(3) distance
  double unitarityError = 0.0;
};

// Runs `method` with `steps` and the kinematic oracle with kinematicSteps,
// and compares them at `samples` arc lengths.
OracleComparison compareWithKinematics(const geometry::ContactPath& path, double R, spin::Method method,
                                       long long steps, long long kinematicSteps, std::size_t samples = 41);

// The same against orientations the oracle already produced at `s`.
OracleComparison compareWithOrientations(const geometry::ContactPath& path, double R, spin::Method method,
                                         long long steps, const std::vector<double>& s,
                                         const std::vector<Eigen::Matrix3d>& oracle);

struct Residuals {
  double slip = 0.0, spin = 0.0;
};
// no slip |dC/ds − R ω × n| and no spin |ω·n|, ω from the solver's quaternions
// by an 8th-order difference of its dense output inside breakpoint segments.
Residuals rollingResiduals(const geometry::ContactPath& path, double R, spin::Method method, long long steps,
                           std::size_t samples = 41);

// Generous step count: 400 per unit of rotation and of length.
long long generousSteps(const geometry::ContactPath& path, double R);

}  // namespace rollspin::test
