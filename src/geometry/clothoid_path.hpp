// The clothoid (Cornu spiral) on a plane: geodesic curvature linear in arc
// length,  κ_g(s) = κ₀ + α s,  s ∈ [0, L],  κ_n = τ_g = 0. The tangent turns
// by φ(s) = κ₀ s + α s²/2 in closed form:
//   t = cos φ e₁ + sin φ e₂,  u = n × t,  e₂ = n × e₁,
// and P(s) = P₀ + ∫₀ˢ t ds (Fresnel integrals) is tabulated once: panels on
// which the tangent turns by ≤ 0.25 rad, each point found by 20-point
// Gauss–Legendre from the panel start and interpolated by a degree-16
// Chebyshev series (|error| ~ 1e-16 relative to the path's extent).
// With κ₀ = −α L/2 the rolling is a Landau–Zener sweep: in the Darboux frame
// the field is (0, 1/R, −κ_g) (frame_propagator.hpp), a constant coupling
// 1/R and a linearly swept detuning.
#pragma once

#include <memory>
#include <vector>

#include "geometry/contact_path.hpp"
#include "geometry/surface.hpp"

namespace rollspin::geometry {

class PlaneClothoidPath final : public ContactPath {
 public:
  // Starts at `start` heading along e1 (a unit vector in the plane).
  PlaneClothoidPath(std::shared_ptr<const Plane> plane, const Vec3& start, const Vec3& e1, double curvature0,
                    double curvatureRate, double length);
  // κ_g from −α L/2 to +α L/2, starting at the origin along the plane's default direction.
  static std::unique_ptr<PlaneClothoidPath> symmetricSweep(double curvatureRate, double length);

  [[nodiscard]] double length() const override { return length_; }
  [[nodiscard]] DarbouxSample at(double s) const override;
  [[nodiscard]] Vec3 point(double s) const override;
  [[nodiscard]] Vec3 normal(double s) const override;
  [[nodiscard]] bool hasConstantCurvatures() const override { return curvatureRate_ == 0.0; }
  [[nodiscard]] std::string describe() const override;
  [[nodiscard]] double turningAngle(double s) const { return s * (kappa0_ + 0.5 * curvatureRate_ * s); }

 private:
  std::shared_ptr<const Plane> plane_;
  Vec3 start_, e1_, e2_;
  double kappa0_, curvatureRate_, length_;
  std::vector<double> panelStarts_;           // s at each panel start (+ length at the end)
  std::vector<std::vector<double>> cx_, cy_;  // Chebyshev coefficients of the offset along e1, e2
  std::vector<double> x0_, y0_;               // in-plane position at each panel start
};

}  // namespace rollspin::geometry
