#include "kinematics/surface_rolling.hpp"

#include "kinematics/rolling_kinematics.hpp"

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <functional>

namespace rollspin::kinematics {

namespace {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
// (u, v, u', v', Q column-major): the curve's place and rate, and the ball's orientation.
using State = Eigen::Matrix<double, 13, 1>;

Mat3 orientationOf(const State& y) { return Eigen::Map<const Mat3>(y.data() + 4); }

// ω_σ = (1/R) n × (x_u u' + x_v v' + R dn/dσ), with dn/dσ from the
// derivative of N = x_u × x_v (header).
Vec3 angularRate(const geometry::SurfaceJet& j, double orientation, const Vec2& rate, double ballRadius) {
  const double a = rate.x(), b = rate.y();
  const Vec3 along = j.xu * a + j.xv * b;
  const Vec3 big = j.xu.cross(j.xv);
  const Vec3 bigRate = (j.xuu * a + j.xuv * b).cross(j.xv) + j.xu.cross(j.xuv * a + j.xvv * b);
  const double size = big.norm();
  const Vec3 unit = big / size;
  const Vec3 normal = orientation * unit;
  const Vec3 normalRate = orientation * (bigRate - unit * unit.dot(bigRate)) / size;
  return normal.cross(along + ballRadius * normalRate) / ballRadius;
}

// The geodesic equation's acceleration (u'', v'').
Vec2 geodesicAcceleration(const geometry::SurfaceJet& j, const Vec2& rate) {
  const double a = rate.x(), b = rate.y();
  const Vec3 second = j.xuu * (a * a) + j.xuv * (2.0 * a * b) + j.xvv * (b * b);
  Eigen::Matrix<double, 3, 2> frame;
  frame << j.xu, j.xv;
  return -(frame.transpose() * frame).ldlt().solve(frame.transpose() * second);
}

using Rate = std::function<State(double sigma, const State& y)>;

// Classical RK4 from y over [start, end] in n steps; the sum carries its
// lost low bits (Kahan), so round-off does not grow with n.
State march(const Rate& f, State y, double start, double end, long long n) {
  const double h = (end - start) / static_cast<double>(n);
  State carry = State::Zero();
  for (long long k = 0; k < n; ++k) {
    const double s = start + static_cast<double>(k) * h;
    const State k1 = f(s, y), k2 = f(s + 0.5 * h, y + (0.5 * h) * k1), k3 = f(s + 0.5 * h, y + (0.5 * h) * k2),
                k4 = f(s + h, y + h * k3);
    const State increment = (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4) - carry;
    const State sum = y + increment;
    carry = (sum - y) - increment;
    y = sum;
  }
  return y;
}

// RK4 is fourth order, so (16 Q_2n − Q_n)/15 cancels the leading error
// term. Done from (n, 2n) and from (2n, 4n): the second is returned, and the
// distance between the two bounds its error (it is well below it).
SurfaceRolling extrapolated(const Rate& f, const State& y0, double start, double end, long long n) {
  const Mat3 q1 = orientationOf(march(f, y0, start, end, n));
  const Mat3 q2 = orientationOf(march(f, y0, start, end, 2 * n));
  const Mat3 q4 = orientationOf(march(f, y0, start, end, 4 * n));
  auto blend = [](const Mat3& coarse, const Mat3& fine) {
    return Mat3(Eigen::Quaterniond(Mat3(fine + (fine - coarse) / 15.0)).normalized().toRotationMatrix());
  };
  const Mat3 first = blend(q1, q2), second = blend(q2, q4);
  SurfaceRolling out;
  out.orientation = second;
  out.ownError = Eigen::AngleAxisd(first.transpose() * second).angle();
  return out;
}

State startState(const Vec2& uv, const Vec2& rate) {
  State y = State::Zero();
  y.head<2>() = uv;
  y.segment<2>(2) = rate;
  Eigen::Map<Mat3>(y.data() + 4) = Mat3::Identity();
  return y;
}

}  // namespace

SurfaceRolling rollAlongCurve(const geometry::Surface& surface, const geometry::UvCurve& curve, double ballRadius,
                              long long steps) {
  const double orientation = surface.orientation();
  // Only Q is integrated: the curve gives (u, v) and (u', v') exactly.
  const Rate f = [&](double sigma, const State& y) {
    const geometry::UvJet c = curve.at(sigma);
    const Vec3 w = angularRate(surface.jet(c.uv), orientation, c.d1, ballRadius);
    State dy = State::Zero();
    Eigen::Map<Mat3>(dy.data() + 4) = skew(w) * orientationOf(y);
    return dy;
  };
  return extrapolated(f, startState(curve.at(curve.start()).uv, Vec2::Zero()), curve.start(), curve.end(), steps);
}

SurfaceRolling rollAlongGeodesic(const geometry::Surface& surface, const Vec2& startUv, const Vec3& startDirection,
                                 double length, double ballRadius, long long steps) {
  const geometry::SurfaceJet j0 = surface.jet(startUv);
  const Vec3 normal = j0.xu.cross(j0.xv).normalized();
  const Vec3 unit = (startDirection - startDirection.dot(normal) * normal).normalized();
  Eigen::Matrix<double, 3, 2> frame;
  frame << j0.xu, j0.xv;
  const Vec2 rate = (frame.transpose() * frame).ldlt().solve(frame.transpose() * unit);
  const double orientation = surface.orientation();
  const Rate f = [&](double, const State& y) {
    const Vec2 uv = y.head<2>(), r = y.segment<2>(2);
    const geometry::SurfaceJet j = surface.jet(uv);
    State dy;
    dy.head<2>() = r;
    dy.segment<2>(2) = geodesicAcceleration(j, r);
    Eigen::Map<Mat3>(dy.data() + 4) = skew(angularRate(j, orientation, r, ballRadius)) * orientationOf(y);
    return dy;
  };
  return extrapolated(f, startState(startUv, rate), 0.0, length, steps);
}

}  // namespace rollspin::kinematics
