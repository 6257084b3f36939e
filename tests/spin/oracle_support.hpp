// Shared by the spin suites: solver runs, the independent kinematic oracle,
// and the continuous SU(2) lift of an SO(3) path (which fixes the spinor sign
// without ever touching the spinor equations).
#pragma once

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "kinematics/rolling_kinematics.hpp"
#include "spin/propagator.hpp"
#include "spin/su2.hpp"

namespace rollspin::test {

inline spin::Su2 solveFinal(const geometry::ContactPath& path, double R, spin::Method m, long long steps) {
  const spin::SolveStats st = spin::Propagator(path, R, m, steps).solveFinal();
  EXPECT_EQ(st.status, spin::SolveStatus::Ok);
  return st.final;
}

// Q(L) from the kinematics, cached per (path, R): the same integration also
// feeds kinematicLift, and it is the expensive part of these tests.
struct KinematicRun {
  Eigen::Matrix3d final;
  spin::Su2 lifted;
};
KinematicRun runKinematics(const geometry::ContactPath& path, double R, std::size_t samples = 4001,
                           long long steps = 40000);

inline Eigen::Matrix3d kinematicFinal(const geometry::ContactPath& path, double R) {
  return runKinematics(path, R).final;
}

inline spin::Su2 fromMatrix(const Eigen::Matrix3d& m) {
  const Eigen::Quaterniond q(m);
  return {q.w(), q.x(), q.y(), q.z()};
}

// Lifts Q(s) (sampled finely enough that neighbours differ by far less than
// π) to SU(2) by continuity from U(0) = +1: the sign the spinor must have.
inline KinematicRun runKinematics(const geometry::ContactPath& path, double R, std::size_t samples, long long steps) {
  // Keyed by what the path is, not where it lives: a freed path's address
  // is soon reused by the next case.
  static std::string lastKey;
  static KinematicRun last;
  const std::string key = path.describe() + "|" + std::to_string(R) + "|" + std::to_string(path.length()) + "|" +
                          std::to_string(samples) + "|" + std::to_string(steps);
  if (key == lastKey) return last;
  const std::vector<double> s = spin::uniformSamples(path.length(), samples);
  const auto qs = kinematics::RollingKinematics(path, R, {steps, 0.0}).orientations(s);
  spin::Su2 prev = spin::Su2::identity();
  for (const auto& m : qs) {
    spin::Su2 q = fromMatrix(m);
    if (q.w * prev.w + q.x * prev.x + q.y * prev.y + q.z * prev.z < 0.0) q = -q;
    prev = q;
  }
  last = {qs.back(), prev};
  lastKey = key;
  return last;
}

inline spin::Su2 kinematicLift(const geometry::ContactPath& path, double R) { return runKinematics(path, R).lifted; }

inline Eigen::Matrix3d rot(const Eigen::Vector3d& axis, double angle) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

}  // namespace rollspin::test
