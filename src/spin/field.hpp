// The rolling field. With the Darboux frame of the contact path,
//   ω(s) = (1/R)(1 − κ_n R) u + τ_g t        (angular velocity per unit s)
//   B(s) = −ω(s) = −[(1/R)(1 − κ_n R) u + τ_g t]      (Rojo & Bloch)
// and the rolling ball is the spin-1/2 equation i dU/ds = −½ B·σ U,
// i.e. dU/ds = −(i/2) ω·σ U, i.e. dQ/ds = [ω]× Q for Q = R(U).
// 1 − κ_n R → 0 simply gives ω → 0; nothing divides by it.
#pragma once

#include <vector>

#include "geometry/contact_path.hpp"
#include "spin/su2.hpp"

namespace rollspin::spin {

[[nodiscard]] inline Vec3 angularVelocity(const geometry::DarbouxSample& f, double ballRadius) {
  return ((1.0 - f.normalCurvature * ballRadius) / ballRadius) * f.tangentNormal + f.geodesicTorsion * f.tangent;
}

[[nodiscard]] inline Vec3 fieldB(const geometry::DarbouxSample& f, double ballRadius) {
  return -angularVelocity(f, ballRadius);
}

// ∫₀ᴸ |B| ds by composite Gauss–Legendre (the rotation budget; the round-off
// floor ε·∫|B| ds).
[[nodiscard]] double integratedFieldStrength(const geometry::ContactPath& path, double ballRadius);
// ∫₀ᴸ (|ω| + |d|) ds, d the Darboux vector: how far the field turns as well
// as how strong it is; sets the automatic step count.
[[nodiscard]] double integratedStepBudget(const geometry::ContactPath& path, double ballRadius);
// The same integral per breakpoint segment (0, breakpoints, L in order): a
// fixed-step march gives each segment steps in proportion, so a corner arc
// of radius r, whose ∫|d| ds is its turn angle whatever r, gets as many steps
// as its turn needs rather than as its (tiny) length would give.
[[nodiscard]] std::vector<double> segmentStepBudgets(const geometry::ContactPath& path, double ballRadius);

}  // namespace rollspin::spin

namespace rollspin::spin {

// Velocity (per unit s) of the ball's point opposite the contact, C + R n:
//   v_top = dC/ds + R ω × n,  dC/ds = (1 − κ_n R) t − R τ_g u.
// On a plane it is 2t: Brockett's upper plate moves twice as fast as the
// contact point, which is how the plate's circle fixes the contact circle.
[[nodiscard]] inline Vec3 topPointVelocity(const geometry::DarbouxSample& f, double ballRadius) {
  const Vec3 centreVelocity =
      (1.0 - f.normalCurvature * ballRadius) * f.tangent - ballRadius * f.geodesicTorsion * f.tangentNormal;
  return centreVelocity + ballRadius * angularVelocity(f, ballRadius).cross(f.normal);
}

}  // namespace rollspin::spin
