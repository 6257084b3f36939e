// The closed forms of rolling, in one place, for the fact labels and the
// paper report. Each is a claim that tests/spin/oracle_test.cpp and
// `rollspin report paper` check against the independent rigid-body
// integration (kinematics/), never against the spinor alone.
//   δ on a plane:     a ball of radius R once round a circle of radius r turns
//                     by δ = 2π √(1 + (r/R)²) about the stick (Rojo–Bloch eq. delta1).
//   δ on a sphere:    along a parallel at colatitude θ (ρ = r sin θ), outside
//                     or inside, δ = 2π √(ρ²/R² + cos²θ) (the kinematics;
//                     docs/solver.md#notes-on-the-paper: why the paper's δ₋ differs).
//   the paper's δ₊:   2π cos θ √(1 + (r tan θ / R)²) (equal to the above outside).
//   the paper's δ₋:   2π √(1 + sin²θ (r − 3R)(r − R)/R²) (the printed, refuted, inside form).
//   Brockett's plate: a plate whose points describe circles of radius R1 drives
//                     the contact point on a circle of radius R1/2 (the top moves
//                     at twice the contact speed).
//   tennis ball:      on a circle of radius r, every path angle β = π/√(1 + (r/R)²)
//                     turns the ball by π (β = π/√2 at r = R).
#pragma once

#include <cmath>
#include <numbers>

namespace rollspin::spin::closed_form {

inline constexpr double kTwoPi = 2.0 * std::numbers::pi;

// Rotation angle per circuit of a circle of radius r on a plane.
[[nodiscard]] inline double planeCircleDelta(double r, double R) { return kTwoPi * std::sqrt(1.0 + (r / R) * (r / R)); }

// Rotation angle per circuit of the parallel at colatitude theta on a sphere
// of radius r, outside or inside.
[[nodiscard]] inline double sphereParallelDelta(double r, double theta, double R) {
  const double rho = r * std::sin(theta), c = std::cos(theta);
  return kTwoPi * std::sqrt(rho * rho / (R * R) + c * c);
}

// The paper's printed forms (claims that `report paper` tests).
[[nodiscard]] inline double paperOutsideDelta(double r, double theta, double R) {
  return kTwoPi * std::cos(theta) * std::sqrt(1.0 + std::pow(r * std::tan(theta) / R, 2));
}
[[nodiscard]] inline double paperInsideDelta(double r, double theta, double R) {
  return kTwoPi * std::sqrt(1.0 + std::pow(std::sin(theta), 2) * (r - 3.0 * R) * (r - R) / (R * R));
}

// The contact circle Brockett's plate drives, from the radius R1 of its points' circles.
[[nodiscard]] inline double brockettContactRadius(double plateRadius) { return plateRadius / 2.0; }

// The path angle between half turns of the ball on a circle of radius r.
[[nodiscard]] inline double tennisBallBeta(double r, double R) {
  return std::numbers::pi / std::sqrt(1.0 + (r / R) * (r / R));
}

}  // namespace rollspin::spin::closed_form
