// A second independent oracle, for curves given on a parametrised surface:
// the rigid-body kinematics of the rolling ball straight from the surface's
// jets (x(u, v) with its exact first and second partial derivatives), with
// no finite differences, no arc-length map, no Darboux frame and no spinor:
//   dQ/dσ = [ω_σ]× Q,   ω_σ = (1/R) n × dC/dσ,   C = x + R n,
//   dC/dσ = x_u u' + x_v v' + R dn/dσ,   n = ς N/|N|,   N = x_u × x_v,
//   dn/dσ = ς (dN/dσ − N̂ (N̂·dN/dσ))/|N|,
//   dN/dσ = (x_uu u' + x_uv v') × x_v + x_u × (x_uv u' + x_vv v'),
// in any parameter σ of the curve (the rotation does not depend on how fast
// the curve is run through), ' = d/dσ. A geodesic is integrated together
// with Q, from its start and unit direction, by its defining equation
// (acceleration normal to the surface):
//   (u'', v'') = −I⁻¹ (x_u·A, x_v·A),   A = x_uu u'² + 2 x_uv u'v' + x_vv v'².
// Classical RK4 on uniform grids of N, 2N and 4N steps with compensated
// summation, Richardson-extrapolated from (2N, 4N); the distance to the
// extrapolation from (N, 2N) is returned as the oracle's own error bound. Where RollingKinematics (finite
// differences of point(s) and normal(s)) stops near 1e-11 rad, this one
// reaches ~1e-14 on smooth curves: it judges errors of 1e-13, such as a
// geodesic path's own integration error (docs/solver.md#the-error-estimate).
// Preconditions: the curve stays where the surface's chart is regular; the
// UvCurve is smooth (no interior breakpoints) on [σ0, σ1].
#pragma once

#include <Eigen/Core>

#include "geometry/surface.hpp"
#include "geometry/uv_curve.hpp"

namespace rollspin::kinematics {

struct SurfaceRolling {
  Eigen::Matrix3d orientation = Eigen::Matrix3d::Identity();  // Q at the end (extrapolated)
  double ownError = 0.0;  // angle between the (N, 2N) and (2N, 4N) extrapolations: a bound on the error
};

// The ball rolling along curve(σ) for σ ∈ [curve.start(), curve.end()], N = `steps`.
[[nodiscard]] SurfaceRolling rollAlongCurve(const geometry::Surface& surface, const geometry::UvCurve& curve,
                                            double ballRadius, long long steps);

// The ball rolling along the geodesic from startUv in the unit tangent
// direction startDirection (a 3-vector in the tangent plane; projected and
// normalised) for arc length `length`, N = `steps`.
[[nodiscard]] SurfaceRolling rollAlongGeodesic(const geometry::Surface& surface, const Eigen::Vector2d& startUv,
                                               const Eigen::Vector3d& startDirection, double length, double ballRadius,
                                               long long steps);

}  // namespace rollspin::kinematics
