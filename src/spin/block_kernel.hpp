// Vectorisable kernel for a full block of 64 Magnus steps on a rigid field
// (constant-curvature path): ω at every node of step j is Rot(d, j h|d|)
// applied to the node's value at the block start, the Magnus vector of each
// step and its su(2) exponential are formed lane-wise, and the 64 step
// elements are multiplied as 4 interleaved chains of 16 (round-off grows
// with 16 + 4, not 64). Data are stored "transposed", position p = 4i + c
// holding step j = 16c + i, so the four chains are four adjacent lanes.
// Bit-identical results on every x86-64 (no FMA contraction; the AVX2 clone
// performs the same IEEE operations in the same order).
#pragma once

#include <cstddef>

#include "spin/su2.hpp"

namespace rollspin::spin::kernel {

inline constexpr std::size_t kBlockSteps = 64;
inline constexpr std::size_t kChains = 4;
inline constexpr std::size_t kChainLength = kBlockSteps / kChains;

// Rotation powers Rot(d, j h|d|), j = 0 … 63, as 9 arrays in transposed order.
struct RotationPowers {
  alignas(64) double m[9][kBlockSteps];
};
void fillRotationPowers(RotationPowers& out, const Vec3& darboux, double h);

// order = 2 (exponential midpoint, one node) or 4 (two Gauss nodes, one
// commutator). anchors[i] = ω at node i of the block's first step.
// Returns E₆₃ ⋯ E₁ E₀, the block's propagator.
Su2 rigidMagnusBlock(int order, double h, const Vec3* anchors, const RotationPowers& powers);

}  // namespace rollspin::spin::kernel
