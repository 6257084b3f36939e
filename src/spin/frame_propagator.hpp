// frame4 — the rolling spinor propagated in the Darboux frame. With
// F(s) = [t u n] (columns), the orientation factors as
//   worldFromBody(s) = F(s) G(s) F(0)ᵀ,   G' = [g(s)]× G,   g = (0, 1/R, −κ_g),
// because Q' = [ω]× Q and F' = [d]× F (d the Darboux vector) leave
// G' = [Fᵀ(ω − d)]× G with ω − d = u/R − κ_g n: κ_n and τ_g drop out, and only
// the geodesic curvature drives the motion in the moving frame. In SU(2):
//   U(s) = Φ(s) V(s) Φ(0)†,  Φ(s) the spinor of F(s),  V' = −(i/2) g·σ V.
// One step from s to s + h applies 4th-order Magnus to V (two Gauss points,
// one commutator) and composes with the frame exactly:
//   U(s+h) = D · Φ(s) exp(Ω_g) Φ(s)† · U(s),   D = Φ(s+h) Φ(s)†,
// where D's sign (the continuous lift) is the one nearer the Magnus estimate
// exp(Ω_d) of the frame's turn (d the Darboux vector at the same Gauss
// points). Exact for constant κ_n, κ_g, τ_g at any h.
#pragma once

#include "geometry/contact_path.hpp"
#include "spin/su2.hpp"

namespace rollspin::spin {

// Spinor of the rotation with columns (t, u, n) (sign: w ≥ 0).
[[nodiscard]] Su2 frameSpinor(const geometry::DarbouxSample& f);

// g(s) = (0, 1/R, −κ_g): the angular velocity in the Darboux frame.
[[nodiscard]] inline Vec3 frameAngularVelocity(const geometry::DarbouxSample& f, double ballRadius) {
  return {0.0, 1.0 / ballRadius, -f.geodesicCurvature};
}

// The frame4 step element E with U(s + h) = E U(s). A march passes `end`,
// its own next node (s + h up to rounding), so that consecutive steps share
// the frame at their common node and the frame factors telescope.
[[nodiscard]] Su2 frame4Element(const geometry::ContactPath& path, double ballRadius, double s, double h, double end);
[[nodiscard]] inline Su2 frame4Element(const geometry::ContactPath& path, double ballRadius, double s, double h) {
  return frame4Element(path, ballRadius, s, h, s + h);
}

}  // namespace rollspin::spin
