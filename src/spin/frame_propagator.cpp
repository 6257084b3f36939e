#include "spin/frame_propagator.hpp"

#include <Eigen/Geometry>

namespace rollspin::spin {

Su2 frameSpinor(const geometry::DarbouxSample& f) {
  Mat3 frame;
  frame.col(0) = f.tangent;
  frame.col(1) = f.tangentNormal;
  frame.col(2) = f.normal;
  // Eigen's matrix → quaternion (Shepperd's method) is well conditioned at any angle.
  const Eigen::Quaterniond q(frame);
  Su2 r{q.w(), q.x(), q.y(), q.z()};
  return r.w < 0.0 ? -r : r;
}

Su2 frame4Element(const geometry::ContactPath& path, double ballRadius, double s, double h) {
  constexpr double c = 0.28867513459481288225;  // √3/6: Gauss points ½ ∓ √3/6
  const geometry::DarbouxSample fa = path.at(s), fb = path.at(s + h);
  const Vec3 g1 = frameAngularVelocity(path.at(s + (0.5 - c) * h), ballRadius);
  const Vec3 g2 = frameAngularVelocity(path.at(s + (0.5 + c) * h), ballRadius);
  const Vec3 magnus = (0.5 * h) * (g1 + g2) + (0.14433756729740644113 * h * h) * g2.cross(g1);  // √3/12
  const Su2 phiA = frameSpinor(fa), phiB = frameSpinor(fb);
  // The frame's own turn over the step, on the short arc (continuous lift).
  Su2 turn = phiB * phiA.conjugate();
  if (turn.w < 0.0) turn = -turn;
  // The moving-frame rotation expressed in world axes at s (sign-free: Φ appears twice).
  const Su2 body = phiA * expRotation(magnus) * phiA.conjugate();
  return turn * body;
}

}  // namespace rollspin::spin
