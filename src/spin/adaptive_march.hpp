// The adaptive march for rk45 and magnus46 (propagator.hpp): steps chosen
// from an error estimate, on each smooth segment between the path's
// breakpoints (a step never crosses one: the last step of a segment is cut to
// land on it), samples reached by one partial step of the base formula from
// the last accepted node, NaN/infinity reported as a status.
//   rk45      Dormand–Prince 5(4), error = RMS of (y₅ − y₄)/(tol + tol|y|) over
//             the four spinor components, accepted when ≤ 1, h ← h·0.9 err^(−1/5);
//   magnus46  Ω₆ advances, est = |Ω₆ − Ω₄| (the 4th-order step's error in
//             radians), accepted when est ≤ tol · h / L (error per unit length, so
//             the sum over the path stays ≤ tol), h ← h·0.9 (tol h/L/est)^(1/4);
//             the step also keeps h·|d| ≤ 1 (the frame turns ≤ 1 rad per step),
//             so the three Gauss nodes cannot alias a fast-turning field.
#pragma once

#include <span>

#include "geometry/contact_path.hpp"
#include "spin/propagator.hpp"

namespace rollspin::spin {

// One step of the adaptive method's base formula (magnus6 or Dormand–Prince
// 5th order) from (s, u) to s + h, no error control: used for partial steps.
[[nodiscard]] Su2 adaptiveStep(const geometry::ContactPath& path, double ballRadius, Method method, const Su2& u,
                               double s, double h);

// The whole march (method rk45 or magnus46, tolerance > 0); seconds is left 0.
[[nodiscard]] SolveStats adaptiveRun(const geometry::ContactPath& path, double ballRadius, Method method,
                                     double tolerance, std::span<const double> sampleS, const SampleSink& sink);

}  // namespace rollspin::spin
