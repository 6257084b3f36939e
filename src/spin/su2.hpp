// Su2 — an element of SU(2) stored as a quaternion q = (w, x, y, z) with
//   U = w·1 − i (x σx + y σy + z σz),
// so that Hamilton's product is the matrix product (U1 U2 ↔ q1 ⊗ q2) and the
// rotation R(U) with U (v·σ) U† = (R v)·σ is the rotation of the unit
// quaternion q. q and −q are different spinors (the 4π story): nothing here
// normalises the sign.
//
// The su(2) exponential in closed form: for a rotation vector v (angle |v|
// about v/|v|), exp(−(i/2) v·σ) = cos(|v|/2) − i sin(|v|/2) v̂·σ, with the
// series of sin(x)/x near x = 0 (no general matrix exponential).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>

namespace rollspin::spin {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

struct Su2 {
  double w = 1.0, x = 0.0, y = 0.0, z = 0.0;

  static Su2 identity() { return {}; }
  [[nodiscard]] Vec3 vec() const { return {x, y, z}; }
  [[nodiscard]] double norm() const { return std::sqrt(w * w + x * x + y * y + z * z); }
  [[nodiscard]] Su2 conjugate() const { return {w, -x, -y, -z}; }
  [[nodiscard]] Su2 operator-() const { return {-w, -x, -y, -z}; }
  [[nodiscard]] bool isFinite() const {
    return std::isfinite(w) && std::isfinite(x) && std::isfinite(y) && std::isfinite(z);
  }
  // The rotation matrix R(U) (exact for unit q; scaled by |q|² otherwise).
  [[nodiscard]] Mat3 rotationMatrix() const;
  // Rotates a vector: R(U) v.
  [[nodiscard]] Vec3 rotate(const Vec3& v) const;
};

// Hamilton product, U1 U2.
[[nodiscard]] inline Su2 operator*(const Su2& a, const Su2& b) {
  return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
          a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}

// cos x and sin(x)/x from x²: even Taylor polynomials in x² below x = 1/4
// (5 terms below x = 1/100, 8 terms above; first omitted terms < 1e-22
// relative), libm beyond. Shared by every exponential so that scalar and
// vectorised steps give bit-identical results.
inline constexpr double kShortSeriesX2 = 1e-4, kLongSeriesX2 = 0.0625;
inline double cosHalfShort(double t) {
  return 1.0 + t * (-1.0 / 2 + t * (1.0 / 24 + t * (-1.0 / 720 + t * (1.0 / 40320))));
}
inline double sincHalfShort(double t) {
  return 1.0 + t * (-1.0 / 6 + t * (1.0 / 120 + t * (-1.0 / 5040 + t * (1.0 / 362880))));
}
inline double cosHalfLong(double t) {
  return 1.0 +
         t * (-1.0 / 2 +
              t * (1.0 / 24 +
                   t * (-1.0 / 720 + t * (1.0 / 40320 +
                                          t * (-1.0 / 3628800 + t * (1.0 / 479001600 + t * (-1.0 / 87178291200.0)))))));
}
inline double sincHalfLong(double t) {
  return 1.0 +
         t * (-1.0 / 6 +
              t * (1.0 / 120 + t * (-1.0 / 5040 +
                                    t * (1.0 / 362880 + t * (-1.0 / 39916800 + t * (1.0 / 6227020800.0 +
                                                                                    t * (-1.0 / 1307674368000.0)))))));
}

// exp(−(i/2) v·σ): the spinor of a rotation by |v| about v/|v|.
[[nodiscard]] Su2 expRotation(const Vec3& v);

// Angle-axis of the SO(3) rotation of q: angle ∈ [0, π] via atan2 (well
// conditioned at 0 and π, unlike acos of the trace); axis unit (x̂ at angle 0).
struct AngleAxis {
  double angle = 0.0;
  Vec3 axis = Vec3::UnitX();
};
[[nodiscard]] AngleAxis rotationAngleAxis(const Su2& q);

// Which sheet q is on: w < −kHalfTurnBand. |w| ≤ kHalfTurnBand (a net angle
// of π up to round-off) counts as w = 0 on the positive sheet, so every method
// reports the same ψ = π and axis at an exact half turn (docs/conventions.md#frames-and-the-spinor).
inline constexpr double kHalfTurnBand = 1e-12;
[[nodiscard]] bool onNegativeSheet(const Su2& q);

// Spinor angle ψ ∈ [0, 4π) with q = (cos ψ/2, sin ψ/2 · axis) for the axis of
// rotationAngleAxis(q): ψ = angle on the positive sheet, angle + 2π on the
// negative one (onNegativeSheet).
[[nodiscard]] double spinorAngle(const Su2& q);

// Geodesic distance between two spinors: the rotation angle of a⁻¹b in
// [0, 2π] *as spinors* (2 atan2(|v|, w) of a†b), so q and −q are 2π apart.
[[nodiscard]] double spinorDistance(const Su2& a, const Su2& b);

// Rotation angle of R(a)ᵀR(b) in [0, π]: the SO(3) distance (sign-blind).
[[nodiscard]] double rotationDistance(const Su2& a, const Su2& b);

}  // namespace rollspin::spin
