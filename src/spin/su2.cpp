#include "spin/su2.hpp"

#include <numbers>

namespace rollspin::spin {

Mat3 Su2::rotationMatrix() const {
  const double ww = w * w, xx = x * x, yy = y * y, zz = z * z;
  Mat3 m;
  m << ww + xx - yy - zz, 2 * (x * y - w * z), 2 * (x * z + w * y),  //
      2 * (x * y + w * z), ww - xx + yy - zz, 2 * (y * z - w * x),   //
      2 * (x * z - w * y), 2 * (y * z + w * x), ww - xx - yy + zz;
  return m;
}

Vec3 Su2::rotate(const Vec3& v) const { return rotationMatrix() * v; }

Su2 expRotation(const Vec3& v) {
  // x = |v|/2; small steps (every stepper's normal case) need no sqrt and no
  // libm call (see the series in su2.hpp).
  const double x2 = 0.25 * v.squaredNorm();
  double cosHalf, sincHalf;
  if (x2 < kShortSeriesX2) {
    cosHalf = cosHalfShort(x2);
    sincHalf = sincHalfShort(x2);
  } else if (x2 < kLongSeriesX2) {
    cosHalf = cosHalfLong(x2);
    sincHalf = sincHalfLong(x2);
  } else {
    const double half = std::sqrt(x2);
    cosHalf = std::cos(half);
    sincHalf = std::sin(half) / half;
  }
  const double k = 0.5 * sincHalf;  // sin(|v|/2)/|v|
  return {cosHalf, k * v.x(), k * v.y(), k * v.z()};
}

AngleAxis rotationAngleAxis(const Su2& q) {
  const double vn = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z);
  AngleAxis aa;
  aa.angle = 2.0 * std::atan2(vn, std::abs(q.w));
  if (vn > 0.0) aa.axis = (onNegativeSheet(q) ? -1.0 : 1.0) * q.vec() / vn;
  return aa;
}

bool onNegativeSheet(const Su2& q) {
  // At a half turn qw is 0 up to round-off, and its sign differs between
  // methods that agree to 1e-13: within kHalfTurnBand it counts as 0, on the
  // positive sheet (ψ = π about the quaternion's own vector part).
  return q.w < -kHalfTurnBand;
}

double spinorAngle(const Su2& q) {
  const double angle = rotationAngleAxis(q).angle;
  return onNegativeSheet(q) ? angle + 2.0 * std::numbers::pi : angle;
}

double spinorDistance(const Su2& a, const Su2& b) {
  const Su2 d = a.conjugate() * b;
  return 2.0 * std::atan2(d.vec().norm(), d.w);
}

double rotationDistance(const Su2& a, const Su2& b) { return rotationAngleAxis(a.conjugate() * b).angle; }

}  // namespace rollspin::spin
