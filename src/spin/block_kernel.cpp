#include "spin/block_kernel.hpp"

#include <Eigen/Geometry>
#include <cmath>

namespace rollspin::spin::kernel {

namespace {
constexpr std::size_t stepOfPosition(std::size_t p) { return (p % kChains) * kChainLength + p / kChains; }
}  // namespace

void fillRotationPowers(RotationPowers& out, const Vec3& darboux, double h) {
  // Rot(j θ) = Rot(8⌊j/8⌋ θ) Rot((j mod 8) θ): 16 direct evaluations instead
  // of 64, each power still within two round-offs of the exact rotation.
  const double rate = darboux.norm();
  const Vec3 axis = rate > 0.0 ? Vec3(darboux / rate) : Vec3::UnitZ();
  Mat3 coarse[8], fine[8];
  for (int k = 0; k < 8; ++k) {
    coarse[k] = Eigen::AngleAxisd(8.0 * k * h * rate, axis).toRotationMatrix();
    fine[k] = Eigen::AngleAxisd(static_cast<double>(k) * h * rate, axis).toRotationMatrix();
  }
  for (std::size_t p = 0; p < kBlockSteps; ++p) {
    const std::size_t j = stepOfPosition(p);
    const Mat3 r = coarse[j / 8] * fine[j % 8];
    for (int k = 0; k < 9; ++k) out.m[k][p] = r(k / 3, k % 3);
  }
}

// The arithmetic below is written as plain loops over the 64 positions so the
// compiler vectorises them; target_clones adds an AVX2 build picked at run
// time, with identical results.
__attribute__((target_clones("avx2", "default"))) Su2 rigidMagnusBlock(int order, double h, const Vec3* anchors,
                                                                       const RotationPowers& powers) {
  constexpr std::size_t n = kBlockSteps;
  alignas(64) double ox[n], oy[n], oz[n];
  const double(*r)[n] = powers.m;
  if (order == 2) {
    const double ax = anchors[0].x(), ay = anchors[0].y(), az = anchors[0].z();
    for (std::size_t p = 0; p < n; ++p) {
      ox[p] = h * (r[0][p] * ax + r[1][p] * ay + r[2][p] * az);
      oy[p] = h * (r[3][p] * ax + r[4][p] * ay + r[5][p] * az);
      oz[p] = h * (r[6][p] * ax + r[7][p] * ay + r[8][p] * az);
    }
  } else {
    const double ax = anchors[0].x(), ay = anchors[0].y(), az = anchors[0].z();
    const double bx = anchors[1].x(), by = anchors[1].y(), bz = anchors[1].z();
    const double half = 0.5 * h, comm = 0.14433756729740644113 * h * h;  // √3/12 h²
    for (std::size_t p = 0; p < n; ++p) {
      const double w1x = r[0][p] * ax + r[1][p] * ay + r[2][p] * az;
      const double w1y = r[3][p] * ax + r[4][p] * ay + r[5][p] * az;
      const double w1z = r[6][p] * ax + r[7][p] * ay + r[8][p] * az;
      const double w2x = r[0][p] * bx + r[1][p] * by + r[2][p] * bz;
      const double w2y = r[3][p] * bx + r[4][p] * by + r[5][p] * bz;
      const double w2z = r[6][p] * bx + r[7][p] * by + r[8][p] * bz;
      // Ω = (h/2)(ω₁ + ω₂) + (√3/12) h² ω₂ × ω₁
      ox[p] = half * (w1x + w2x) + comm * (w2y * w1z - w2z * w1y);
      oy[p] = half * (w1y + w2y) + comm * (w2z * w1x - w2x * w1z);
      oz[p] = half * (w1z + w2z) + comm * (w2x * w1y - w2y * w1x);
    }
  }
  // exp(−(i/2) Ω·σ) lane-wise, with the series tier of the block's largest
  // angle. A lane below that tier gets the longer series, which agrees with
  // the shorter one to round-off; past 1/4 every lane takes expRotation().
  alignas(64) double ew[n], ex[n], ey[n], ez[n];
  double largest = 0.0;
  alignas(64) double x2[n];
  for (std::size_t p = 0; p < n; ++p) {
    x2[p] = 0.25 * (ox[p] * ox[p] + oy[p] * oy[p] + oz[p] * oz[p]);
    largest = largest > x2[p] ? largest : x2[p];
  }
  if (largest < kShortSeriesX2) {
    for (std::size_t p = 0; p < n; ++p) {
      ew[p] = cosHalfShort(x2[p]);
      const double k = 0.5 * sincHalfShort(x2[p]);
      ex[p] = k * ox[p], ey[p] = k * oy[p], ez[p] = k * oz[p];
    }
  } else if (largest < kLongSeriesX2) {
    for (std::size_t p = 0; p < n; ++p) {
      ew[p] = cosHalfLong(x2[p]);
      const double k = 0.5 * sincHalfLong(x2[p]);
      ex[p] = k * ox[p], ey[p] = k * oy[p], ez[p] = k * oz[p];
    }
  } else {
    for (std::size_t p = 0; p < n; ++p) {
      const Su2 e = expRotation(Vec3(ox[p], oy[p], oz[p]));
      ew[p] = e.w, ex[p] = e.x, ey[p] = e.y, ez[p] = e.z;
    }
  }
  // Four chains side by side: acc_c ← E ⊗ acc_c over i = 0 … 15.
  double aw[kChains] = {1, 1, 1, 1}, axq[kChains] = {0, 0, 0, 0}, ayq[kChains] = {0, 0, 0, 0},
         azq[kChains] = {0, 0, 0, 0};
  for (std::size_t i = 0; i < kChainLength; ++i) {
    for (std::size_t c = 0; c < kChains; ++c) {
      const std::size_t p = i * kChains + c;
      const double w = ew[p] * aw[c] - ex[p] * axq[c] - ey[p] * ayq[c] - ez[p] * azq[c];
      const double x = ew[p] * axq[c] + ex[p] * aw[c] + ey[p] * azq[c] - ez[p] * ayq[c];
      const double y = ew[p] * ayq[c] - ex[p] * azq[c] + ey[p] * aw[c] + ez[p] * axq[c];
      const double z = ew[p] * azq[c] + ex[p] * ayq[c] - ey[p] * axq[c] + ez[p] * aw[c];
      aw[c] = w, axq[c] = x, ayq[c] = y, azq[c] = z;
    }
  }
  const Su2 c0{aw[0], axq[0], ayq[0], azq[0]}, c1{aw[1], axq[1], ayq[1], azq[1]}, c2{aw[2], axq[2], ayq[2], azq[2]},
      c3{aw[3], axq[3], ayq[3], azq[3]};
  return (c3 * c2) * (c1 * c0);
}

}  // namespace rollspin::spin::kernel
