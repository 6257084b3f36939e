// The adaptive march for rk45 and frame6a (propagator.hpp): steps chosen
// from an error estimate, on each smooth segment between the path's
// breakpoints (a step never crosses one: the last step of a segment is cut to
// land on it), samples reached by one partial step of the base formula from
// the last accepted node, NaN/infinity reported as a status. The arc length
// is accumulated with a compensated sum, so millions of steps do not drift
// the field's argument (an error δs costs |ω| δs of orientation).
//   rk45     Dormand–Prince 5(4) on the raw spinor, error = RMS over the four
//            components of (y₅ − y₄)/(tol + tol|y|), accepted when ≤ 1,
//            h ← h · 0.9 err^(−1/5) (the usual per-step control).
//   frame6a  the Darboux-frame factorisation of frame4 (frame_propagator.hpp):
//              E(s, h) = Φ(s+h) exp(Ω_g) Φ(s)†,  g = (0, 1/R, −κ_g),
//            with Ω_g the magnus6 exponent of g on [s, s+h]; the frame factor
//            is exact, so only the variation of κ_g costs steps (constant κ_g:
//            exact at any h, whatever |B| h). Error by step doubling,
//            err = dist(E(s,h), E(s+h/2,h/2) E(s,h/2)) / 63, accepted when
//            err ≤ max(tol · h / L, 8ε) (per unit length: the sum stays ≤ tol,
//            but no step is asked for less than round-off), the
//            two half steps advance, h ← h · 0.9 (tol h / L / err)^(1/6).
//            The frame factor's sign is the one nearer exp(h d_mid); on a
//            path whose curvatures vary, the frame may turn by at most 2.5
//            rad per step (h·|d| ≤ 2.5 at the nodes) so that this estimate
//            stays within π of the truth; on constant curvatures there is no
//            cap (everything is exact at any h).
#pragma once

#include <span>

#include "geometry/contact_path.hpp"
#include "spin/propagator.hpp"

namespace rollspin::spin {

// One step of the adaptive method's base formula (the frame6 element or the
// Dormand–Prince 5th-order step) from (s, u) to s + h, no error control.
[[nodiscard]] Su2 adaptiveStep(const geometry::ContactPath& path, double ballRadius, Method method, const Su2& u,
                               double s, double h);

// The whole march (method rk45 or frame6a, tolerance > 0, at most stepLimit
// attempted steps); seconds is left 0.
[[nodiscard]] SolveStats adaptiveRun(const geometry::ContactPath& path, double ballRadius, Method method,
                                     double tolerance, long long stepLimit, const SampleArcLengths& sampleS,
                                     const SampleSink& sink);

}  // namespace rollspin::spin
