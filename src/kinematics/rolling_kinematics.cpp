#include "kinematics/rolling_kinematics.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>

namespace rollspin::kinematics {

void firstDerivativeWeights(std::span<const double> nodes, double x0, std::span<double> weights) {
  // Fornberg (1988), "Generation of finite difference formulas on arbitrarily
  // spaced grids", specialised to derivative orders 0 and 1. Row i of the
  // tables needs only row i − 1: two rows each, on the stack (the same
  // operations in the same order as the full tables, so the same bits).
  const std::size_t n = nodes.size();
  assert(n >= 1 && n <= kMaxDerivativeNodes && weights.size() == n);
  std::array<double, kMaxDerivativeNodes> c0prev{}, c1prev{}, c0{}, c1{};
  c0[0] = 1.0;
  double c1prod = 1.0;
  for (std::size_t i = 1; i < n; ++i) {
    c0prev = c0;
    c1prev = c1;
    double c2 = 1.0;
    for (std::size_t j = 0; j < i; ++j) {
      const double c3 = nodes[i] - nodes[j];
      c2 *= c3;
      c1[j] = ((nodes[i] - x0) * c1prev[j] - c0prev[j]) / c3;
      c0[j] = ((nodes[i] - x0) * c0prev[j]) / c3;
    }
    c1[i] = c1prod / c2 * (c0prev[i - 1] - (nodes[i - 1] - x0) * c1prev[i - 1]);
    c0[i] = -c1prod / c2 * (nodes[i - 1] - x0) * c0prev[i - 1];
    c1prod = c2;
  }
  std::copy_n(c1.begin(), n, weights.begin());
}

std::vector<double> firstDerivativeWeights(std::span<const double> nodes, double x0) {
  std::vector<double> weights(nodes.size());
  firstDerivativeWeights(nodes, x0, weights);
  return weights;
}

RollingKinematics::RollingKinematics(const geometry::ContactPath& path, double ballRadius, KinematicSettings settings)
    : path_(path), ballRadius_(ballRadius), settings_(settings) {
  cuts_.push_back(0.0);
  for (double b : path_.breakpoints())
    if (b > 0.0 && b < path_.length()) cuts_.push_back(b);
  cuts_.push_back(path_.length());
  // Per segment: balance truncation (h⁸ C⁽⁹⁾) against round-off (ε|C|/h)
  // with a spacing of about 1e-2 of the segment's shortest length scale — R,
  // the segment's length, and the radii on which P and n turn there. Those
  // radii are estimated from P and n themselves (second and first
  // differences on a coarse grid), never from κ. Per segment, so that a tiny
  // corner arc does not shrink the spacing (and grow the round-off) on the
  // long straight pieces.
  const double length = path_.length();
  for (std::size_t seg = 0; seg + 1 < cuts_.size(); ++seg) {
    const double a = cuts_[seg], b = cuts_[seg + 1], d = (b - a) / 512.0;
    double turning = 0.0;  // max |P''| and |n'| seen
    for (int k = 1; k < 512; k += 4) {
      const double s = a + k * d;
      const Vec3 p0 = path_.point(s - d), p1 = path_.point(s), p2 = path_.point(s + d);
      turning = std::max(turning, (p2 - 2.0 * p1 + p0).norm() / (d * d));
      turning = std::max(turning, (path_.normal(s + d) - path_.normal(s - d)).norm() / (2.0 * d));
    }
    double scale = std::min(ballRadius_, (b - a) / 8.0);
    if (turning > 0.0 && std::isfinite(turning)) scale = std::min(scale, 1.0 / turning);
    fdSteps_.push_back(settings_.fdStep > 0.0 ? settings_.fdStep : settings_.fdFraction * scale);
    const double byLength = static_cast<double>(settings_.steps) * (b - a) / std::max(length, 1e-300);
    const double byTurn =
        settings_.minStepsPerRadian * (b - a) * ((std::isfinite(turning) ? turning : 0.0) + 1.0 / ballRadius_);
    segmentSteps_.push_back(std::max<long long>(1, std::llround(std::max(byLength, std::ceil(byTurn)))));
  }
}

Vec3 RollingKinematics::centre(double s) const { return path_.point(s) + ballRadius_ * path_.normal(s); }

Vec3 RollingKinematics::centreVelocity(double s) const {
  // Segment containing s (a node on a cut belongs to the segment it starts,
  // except the end point).
  std::size_t seg = 0;
  while (seg + 2 < cuts_.size() && s >= cuts_[seg + 1]) ++seg;
  return centreVelocity(s, seg);
}

Vec3 RollingKinematics::centreVelocity(double s, std::size_t seg) const {
  const double a = cuts_[seg], b = cuts_[seg + 1], h = fdSteps_[seg];
  // 9 nodes, centred when possible, shifted to stay inside [a, b]: 8th order.
  double first = s - 4.0 * h;
  if (first < a) first = a;
  if (first + 8.0 * h > b) first = std::max(a, b - 8.0 * h);
  double nodes[9];
  for (int k = 0; k < 9; ++k) nodes[k] = first + k * h;
  double w[9];
  firstDerivativeWeights(nodes, s, w);
  Vec3 v = Vec3::Zero();
  for (int k = 0; k < 9; ++k) v += w[k] * centre(nodes[k]);
  return v;
}

Vec3 RollingKinematics::omega(double s) const { return path_.normal(s).cross(centreVelocity(s)) / ballRadius_; }

Vec3 RollingKinematics::omega(double s, std::size_t seg) const {
  return path_.normal(s).cross(centreVelocity(s, seg)) / ballRadius_;
}

Mat3 RollingKinematics::rk4Increment(const Mat3& q, double s, double h, std::size_t seg) const {
  const Mat3 wa = skew(omega(s, seg)), wb = skew(omega(s + 0.5 * h, seg)), wc = skew(omega(s + h, seg));
  const Mat3 k1 = wa * q;
  const Mat3 k2 = wb * (q + 0.5 * h * k1);
  const Mat3 k3 = wb * (q + 0.5 * h * k2);
  const Mat3 k4 = wc * (q + h * k3);
  return (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
}

std::vector<Mat3> RollingKinematics::orientations(std::span<const double> sampleS) const {
  std::vector<Mat3> out;
  out.reserve(sampleS.size());
  // Q accumulates small increments over tens of thousands of steps: each
  // addition rounds by ε|Q|, which summed to ~1e-12 rad at 20,000 steps (and
  // grew with more). Compensated (Kahan) summation carries the lost low
  // bits, so the oracle's floor is its truncation and differences, not N ε.
  Mat3 q = Mat3::Identity(), carry = Mat3::Zero();
  std::size_t next = 0;
  for (std::size_t seg = 0; seg + 1 < cuts_.size(); ++seg) {
    const double a = cuts_[seg], b = cuts_[seg + 1];
    const long long n = segmentSteps_[seg];
    const double h = (b - a) / static_cast<double>(n);
    for (long long k = 0; k < n; ++k) {
      const double s = a + static_cast<double>(k) * h;
      const double sNext = (k + 1 == n) ? b : s + h;
      while (next < sampleS.size() && sampleS[next] < sNext) {
        const double dh = std::max(0.0, sampleS[next] - s);
        out.push_back(dh == 0.0 ? q : Mat3(q + rk4Increment(q, s, dh, seg)));
        ++next;
      }
      const Mat3 increment = rk4Increment(q, s, sNext - s, seg) - carry;
      const Mat3 sum = q + increment;
      carry = (sum - q) - increment;
      q = sum;
    }
  }
  while (next < sampleS.size()) {
    out.push_back(q);
    ++next;
  }
  return out;
}

Mat3 RollingKinematics::finalOrientation() const {
  const double end[1] = {path_.length()};
  return orientations(end).front();
}

}  // namespace rollspin::kinematics
