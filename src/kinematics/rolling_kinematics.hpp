// Independent oracle for the rolling ball: integrates the rigid-body
// kinematics in SO(3),
//   dQ/ds = [ω]× Q,   ω = (1/R) n × dC/ds,   C(s) = P(s) + R n(s),   Q(0) = 1,
// with classical RK4 on the nine entries of Q and dC/ds from high-order
// finite differences of C. It reads only ContactPath::point and ::normal
// (the surface's own point and normal functions): no curvature, no Darboux
// frame, no spinor. Precondition: point/normal are smooth on each breakpoint
// segment; stencils stay inside the segment they differentiate.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <span>
#include <vector>

#include "geometry/contact_path.hpp"

namespace rollspin::kinematics {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

// [w]×: the matrix of w × (·), so that [w]× v = w × v.
inline Mat3 skew(const Vec3& w) {
  Mat3 m;
  m << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
  return m;
}

struct KinematicSettings {
  long long steps = 20000;  // RK4 steps over the whole path, shared by length
  double fdStep = 0.0;      // finite-difference spacing; 0 → automatic, per segment
  // At least this many steps per radian that ω turns or the ball rolls in a
  // segment (length · (max|P''|, |n'| seen + 1/R)): a corner arc of radius
  // r ≪ R turns ω through its whole angle in a length ∝ r, which a share by
  // length leaves to one step. 0: by length only.
  double minStepsPerRadian = 0.0;
  // Automatic spacing as a fraction of the segment's shortest length scale.
  // 1e-2 leaves a round-off of ~ε|C|/(1e-2 scale) in dC/ds; near 4e-2 the
  // 8th-order truncation and the round-off balance, about 10× lower.
  double fdFraction = 1e-2;
};

class RollingKinematics {
 public:
  RollingKinematics(const geometry::ContactPath& path, double ballRadius, KinematicSettings settings = {});

  // C(s) = P(s) + R n(s).
  [[nodiscard]] Vec3 centre(double s) const;
  // dC/ds by an 8th-order finite-difference stencil inside s's segment.
  [[nodiscard]] Vec3 centreVelocity(double s) const;
  // ω(s) = (1/R) n × dC/ds.
  [[nodiscard]] Vec3 omega(double s) const;
  // Q at each s of sampleS (non-decreasing, inside [0, L]).
  [[nodiscard]] std::vector<Mat3> orientations(std::span<const double> sampleS) const;
  [[nodiscard]] Mat3 finalOrientation() const;

 private:
  // One RK4 step's increment Q(s + h) − Q(s) inside segment `seg` (its end
  // node, on the cut, is differentiated from this segment's side: at a
  // corner dC/ds jumps).
  [[nodiscard]] Mat3 rk4Increment(const Mat3& q, double s, double h, std::size_t seg) const;
  [[nodiscard]] Vec3 centreVelocity(double s, std::size_t seg) const;
  [[nodiscard]] Vec3 omega(double s, std::size_t seg) const;
  const geometry::ContactPath& path_;
  double ballRadius_;
  KinematicSettings settings_;
  std::vector<double> cuts_;             // 0, breakpoints, L
  std::vector<double> fdSteps_;          // finite-difference spacing per segment
  std::vector<long long> segmentSteps_;  // RK4 steps per segment
};

// Fornberg's weights for the first derivative at x0 from values at nodes x.
// The span form writes them into `weights` (nodes.size() of them, at most
// kMaxDerivativeNodes) without touching the heap: the march calls it three
// times a step.
inline constexpr std::size_t kMaxDerivativeNodes = 16;
void firstDerivativeWeights(std::span<const double> nodes, double x0, std::span<double> weights);
[[nodiscard]] std::vector<double> firstDerivativeWeights(std::span<const double> nodes, double x0);

}  // namespace rollspin::kinematics
