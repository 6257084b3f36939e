// spin/block_kernel: the rotation powers in transposed order, and a 64-step Magnus block on a rigidly turning field.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "spin/block_kernel.hpp"

namespace rollspin::spin::kernel {
namespace {

// Rodrigues: the rotation by φ about the unit k, I cos φ + [k]× sin φ + k kᵀ (1 − cos φ).
Mat3 rodriguesRotation(const Vec3& k, double phi) {
  Mat3 cross;
  cross << 0, -k.z(), k.y(), k.z(), 0, -k.x(), -k.y(), k.x(), 0;
  return std::cos(phi) * Mat3::Identity() + std::sin(phi) * cross + (1.0 - std::cos(phi)) * k * k.transpose();
}

// The spinor of the rotation by |v| about v̂ from its half angle, no sign
// normalised: (cos |v|/2, sin |v|/2 v̂).
Su2 blockTestSpinorOf(const Vec3& v) {
  const double angle = v.norm();
  if (angle == 0.0) return Su2::identity();
  const Vec3 s = std::sin(0.5 * angle) * v / angle;
  return {std::cos(0.5 * angle), s.x(), s.y(), s.z()};
}

// A field turning rigidly about d, ω(s) = Rot(d, s|d|) ω₀. U' = −(i/2) ω·σ U
// (Q' = [ω]× Q) has the closed form Q(s) = Rot(d, s|d|) Rot(ω₀ − d, s|ω₀ − d|):
//   Q' = [d]× Q + Rot(d) [ω₀ − d]× Rot(d)ᵀ Q = [d + Rot(d)(ω₀ − d)]× Q = [ω(s)]× Q,
// as Rot(d) d = d; as spinors, continuous from U(0) = 1 (the sign too):
//   U(s) = e(s d) e(s (ω₀ − d)).
struct RigidField {
  Vec3 d, omega0;
  [[nodiscard]] Vec3 omegaAt(double s) const {
    const double rate = d.norm();
    return rate > 0.0 ? Vec3(rodriguesRotation(d / rate, s * rate) * omega0) : omega0;
  }
  [[nodiscard]] Su2 exactAt(double s) const { return blockTestSpinorOf(s * d) * blockTestSpinorOf(s * (omega0 - d)); }
};

// `blocks` consecutive blocks of 64 steps of h from s = 0, composed:
// anchors at the exponential midpoint (order 2) or the two Gauss points
// ½ ∓ √3/6 (order 4) of each block's first step.
Su2 marchBlocks(const RigidField& field, int order, double h, int blocks) {
  RotationPowers powers;
  fillRotationPowers(powers, field.d, h);
  const std::vector<double> nodes =
      order == 2 ? std::vector<double>{0.5} : std::vector<double>{0.5 - std::sqrt(3.0) / 6, 0.5 + std::sqrt(3.0) / 6};
  Su2 u = Su2::identity();
  for (int b = 0; b < blocks; ++b) {
    const double start = double(kBlockSteps) * h * b;
    Vec3 anchors[2];
    for (std::size_t i = 0; i < nodes.size(); ++i) anchors[i] = field.omegaAt(start + nodes[i] * h);
    u = rigidMagnusBlock(order, h, anchors, powers) * u;
  }
  return u;
}

// Position p holds step j = 16 (p mod 4) + ⌊p/4⌋, so the four chains of 16
// steps are four adjacent lanes; each entry is Rot(d, j h|d|) to round-off.
TEST(RotationPowers, HoldEachStepsRotationInTransposedOrder) {
  const Vec3 d(0.3, -0.4, 1.2);  // |d| = 1.3
  const double h = 0.061;        // up to 63 h|d| ≈ 5 rad
  RotationPowers powers;
  fillRotationPowers(powers, d, h);
  for (std::size_t p = 0; p < kBlockSteps; ++p) {
    const std::size_t j = 16 * (p % 4) + p / 4;
    const Mat3 expected = rodriguesRotation(d / d.norm(), double(j) * h * d.norm());
    for (int k = 0; k < 9; ++k) ASSERT_NEAR(powers.m[k][p], expected(k / 3, k % 3), 1e-14) << "p " << p << " k " << k;
  }
}

TEST(RotationPowers, AreTheIdentityWhenTheFieldDoesNotTurn) {
  RotationPowers powers;
  fillRotationPowers(powers, Vec3::Zero(), 0.25);
  for (std::size_t p = 0; p < kBlockSteps; ++p)
    for (int k = 0; k < 9; ++k) ASSERT_EQ(powers.m[k][p], k % 4 == 0 ? 1.0 : 0.0) << "p " << p << " k " << k;
}

// A field that does not turn (d = 0, or ω₀ ∥ d) is constant: every step
// element is the same rotation and the block is e(64 h ω₀) exactly, sign
// included, at both orders and with step angles in each of the three tiers
// of the exponential (short series, long series, libm): 64 h|ω₀| from
// 0.07 rad to 38 rad, six whole turns and more.
TEST(RigidMagnusBlock, AConstantFieldGivesTheExactRotationInEveryTier) {
  const Vec3 omega0(0.6, -0.8, 0.48);  // |ω₀| ≈ 1.11
  for (const Vec3& d : {Vec3(Vec3::Zero()), Vec3(1.25 * omega0)})
    for (double h : {0.001, 0.05, 0.6})
      for (int order : {2, 4}) {
        const RigidField field{d, omega0};
        const Su2 block = marchBlocks(field, order, h, 1);
        const Su2 expected = blockTestSpinorOf(double(kBlockSteps) * h * omega0);
        EXPECT_LE(spinorDistance(block, expected), 1e-13) << "d " << d.transpose() << " h " << h << " order " << order;
      }
}

// A field that turns: the block's product of 64 non-commuting steps
// converges to the closed form at the order asked for (the error of the
// same length falls 4× or 16× when h halves), sign included.
TEST(RigidMagnusBlock, ConvergesToTheRigidFieldsClosedFormAtItsOrder) {
  const RigidField field{Vec3(0.3, -0.4, 1.2), Vec3(1.5, 0.7, -0.2)};
  for (int order : {2, 4}) {
    const double h = order == 2 ? 0.02 : 0.05, length = double(kBlockSteps) * h;
    const Su2 exact = field.exactAt(length);
    std::vector<double> errors;
    for (int blocks : {1, 2, 4}) {
      errors.push_back(spinorDistance(marchBlocks(field, order, h / blocks, blocks), exact));
      if (std::getenv("ROLLSPIN_VERBOSE")) std::printf("order %d, %d blocks: %.3e\n", order, blocks, errors.back());
    }
    const double expectedRatio = order == 2 ? 4.0 : 16.0;
    EXPECT_GT(errors[0], 1e-9) << "order " << order << ": the order must show above round-off";
    for (std::size_t k = 1; k < errors.size(); ++k) {
      EXPECT_NEAR(errors[k - 1] / errors[k], expectedRatio, 0.15 * expectedRatio) << "order " << order << " " << k;
    }
  }
}

}  // namespace
}  // namespace rollspin::spin::kernel
