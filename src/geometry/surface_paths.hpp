// The named curves on surfaces, each built as a UvCurve in the surface's
// parameters and wrapped in a SurfaceCurvePath (arc length, Darboux frame):
//   parallel   circle about the axis of a surface of revolution
//              (sphere θ = θ0; cylinder z = z0; torus ψ = ψ0; paraboloid ρ = ρ0),
//              counter-clockwise about the axis when ccw;
//   meridian   the profile curve at azimuth φ0 (sphere θ: θ0 → θ1; torus ψ:
//              ψ0 → ψ0 ± 2π turns; cylinder z: z0 → z0 + length; height field:
//              the vertical section ρ ∈ [−length/2, length/2] through the z axis);
//   helix      on a cylinder: φ = ±σ, z = z0 + a tan β σ (pitch angle β from the
//              parallels), so κ_n = −cos²β/a (outside), |τ_g| = sin β cos β/a;
//   loxodrome  on a sphere, crossing every meridian at heading α:
//              φ(θ) = φ0 + tan α ln(tan(θ/2)/tan(θ0/2)), θ: θ0 → θ1;
//   geodesic   u'' = −Γ(u', u') integrated in arc length from a point and a
//              tangent direction (RK4, h ≤ 1/500 of a unit, then fitted by
//              Chebyshev panels: |κ_g| ~ 1e-9, not chords);
//   uv         u(t), v(t) expressions for t ∈ [t0, t1];
//   points     a cubic spline (open or periodic) or a polyline with rounded
//              corners through control points in the surface's parameters.
#pragma once

#include <memory>
#include <vector>

#include "geometry/expression.hpp"
#include "geometry/surface_curve.hpp"
#include "geometry/surfaces.hpp"

namespace rollspin::geometry {

// Parallels start at azimuth startAzimuth (radians; 0 by default: φ = 0 on
// the surface's own azimuth, see docs/conventions.md) and run ±2π·turns.
[[nodiscard]] std::unique_ptr<SurfaceCurvePath> sphereParallel(std::shared_ptr<const Sphere> sphere, double colatitude,
                                                               double turns, bool ccw, double startAzimuth = 0.0);
[[nodiscard]] std::unique_ptr<SurfaceCurvePath> cylinderParallel(std::shared_ptr<const Cylinder> cylinder,
                                                                 double height, double turns, bool ccw,
                                                                 double startAzimuth = 0.0);
[[nodiscard]] std::unique_ptr<SurfaceCurvePath> torusParallel(std::shared_ptr<const Torus> torus, double tubeAngle,
                                                              double turns, bool ccw, double startAzimuth = 0.0);
// Requires a surface of revolution (paraboloid with a = b).
[[nodiscard]] std::unique_ptr<SurfaceCurvePath> heightFieldParallel(std::shared_ptr<const HeightField> field,
                                                                    double radius, double turns, bool ccw,
                                                                    double startAzimuth = 0.0);

[[nodiscard]] std::unique_ptr<SurfaceCurvePath> sphereMeridian(std::shared_ptr<const Sphere> sphere, double azimuth,
                                                               double colatitudeStart, double colatitudeEnd);
[[nodiscard]] std::unique_ptr<SurfaceCurvePath> torusMeridian(std::shared_ptr<const Torus> torus, double azimuth,
                                                              double tubeAngleStart, double turns, bool ccw);
[[nodiscard]] std::unique_ptr<SurfaceCurvePath> cylinderMeridian(std::shared_ptr<const Cylinder> cylinder,
                                                                 double azimuth, double height, double length);
[[nodiscard]] std::unique_ptr<SurfaceCurvePath> heightFieldMeridian(std::shared_ptr<const HeightField> field,
                                                                    double azimuth, double length);

[[nodiscard]] std::unique_ptr<SurfaceCurvePath> cylinderHelix(std::shared_ptr<const Cylinder> cylinder,
                                                              double pitchAngle, double height, double turns, bool ccw);
[[nodiscard]] std::unique_ptr<SurfaceCurvePath> sphereLoxodrome(std::shared_ptr<const Sphere> sphere, double heading,
                                                                double azimuth, double colatitudeStart,
                                                                double colatitudeEnd);

// direction: any vector with a component in the tangent plane at start
// (projected onto it). Throws GeometryError if the geodesic leaves the domain.
// Off the sphere the path is integrated and fitted; its finerApproximation()
// is the same geodesic marched at half the step (compensated sums, no fit,
// in arc length), for the error estimate.
[[nodiscard]] std::unique_ptr<SurfaceCurvePath> geodesicPath(std::shared_ptr<const Surface> surface,
                                                             const Vec2& startUv, const Vec3& direction, double length);

[[nodiscard]] std::unique_ptr<SurfaceCurvePath> uvExpressionPath(std::shared_ptr<const Surface> surface,
                                                                 std::shared_ptr<const Expression> u,
                                                                 std::shared_ptr<const Expression> v, double tStart,
                                                                 double tEnd);

enum class PointsInterpolation { CubicSpline, Polyline };
[[nodiscard]] std::unique_ptr<SurfaceCurvePath> pointsPath(std::shared_ptr<const Surface> surface,
                                                           const std::vector<Vec2>& pointsUv, bool closed,
                                                           PointsInterpolation interpolation, double cornerRadius);

}  // namespace rollspin::geometry
