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

Su2 frame4Element(const geometry::ContactPath& path, double ballRadius, double s, double h, double end) {
  constexpr double c = 0.28867513459481288225;  // √3/6: Gauss points ½ ∓ √3/6
  constexpr double k = 0.14433756729740644113;  // √3/12
  const geometry::DarbouxSample fa = path.at(s), fb = path.at(end);
  const geometry::DarbouxSample f1 = path.at(s + (0.5 - c) * h), f2 = path.at(s + (0.5 + c) * h);
  const Vec3 g1 = frameAngularVelocity(f1, ballRadius), g2 = frameAngularVelocity(f2, ballRadius);
  const Vec3 magnus = (0.5 * h) * (g1 + g2) + (k * h * h) * g2.cross(g1);
  const Su2 phiA = frameSpinor(fa), phiB = frameSpinor(fb);
  // The frame's own turn over the step, D = Φ(s+h) Φ(s)†, known up to sign
  // from the two frames. The continuous lift is the sign nearer the Magnus
  // estimate of the frame's turn, exp(Ω_d) with F' = [d]× F: correct while
  // that estimate is within π of the truth, even when the frame turns by a
  // full circle or more within one step (exact for constant curvatures).
  const Vec3 d1 = geometry::darbouxVector(f1), d2 = geometry::darbouxVector(f2);
  const Su2 predicted = expRotation((0.5 * h) * (d1 + d2) + (k * h * h) * d2.cross(d1));
  Su2 turn = phiB * phiA.conjugate();
  if (turn.w * predicted.w + turn.x * predicted.x + turn.y * predicted.y + turn.z * predicted.z < 0.0) turn = -turn;
  // The moving-frame rotation expressed in world axes at s (sign-free: Φ appears twice).
  const Su2 body = phiA * expRotation(magnus) * phiA.conjugate();
  return turn * body;
}

}  // namespace rollspin::spin
