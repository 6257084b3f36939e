// Contact paths with constant curvatures, in closed form (the foundation's
// line, circle and parallel). Each keeps the Surface it lies on, and point(s)
// / normal(s) go through the curve's position and that surface's normal, so
// the kinematic oracle never sees the closed-form frame below.
//
// Line on a plane:        κ_n = κ_g = τ_g = 0.
// Circle (radius ρ) on a plane, direction σ = ±1 about n:
//                          κ_g = σ/ρ, κ_n = τ_g = 0.
// Parallel at colatitude θ on a sphere of radius r, side ς = ±1 (outside /
// inside), direction σ = ±1 about +z, ρ = r sin θ:
//                          κ_n = −ς/r,  κ_g = ς σ cot θ / r,  τ_g = 0.
#pragma once

#include <memory>

#include "geometry/contact_path.hpp"
#include "geometry/surface.hpp"

namespace rollspin::geometry {

class PlaneLinePath final : public ContactPath {
 public:
  // direction must be a unit vector perpendicular to the plane's normal.
  PlaneLinePath(std::shared_ptr<const Plane> plane, const Vec3& start, const Vec3& direction, double length);
  [[nodiscard]] double length() const override { return length_; }
  [[nodiscard]] DarbouxSample at(double s) const override;
  [[nodiscard]] Vec3 point(double s) const override;
  [[nodiscard]] Vec3 normal(double s) const override;
  [[nodiscard]] bool hasConstantCurvatures() const override { return true; }
  [[nodiscard]] std::string describe() const override;

 private:
  std::shared_ptr<const Plane> plane_;
  Vec3 start_, direction_;
  double length_;
};

class PlaneCirclePath final : public ContactPath {
 public:
  // A circle of `radius` about `centre` in the plane, starting at
  // centre + radius·e1 (e1 a unit vector in the plane), counter-clockwise
  // about the plane normal when counterClockwise (seen from the ball's side).
  PlaneCirclePath(std::shared_ptr<const Plane> plane, const Vec3& centre, const Vec3& e1, double radius, double turns,
                  bool counterClockwise);
  [[nodiscard]] double length() const override;
  [[nodiscard]] DarbouxSample at(double s) const override;
  [[nodiscard]] Vec3 point(double s) const override;
  [[nodiscard]] Vec3 normal(double s) const override;
  [[nodiscard]] bool hasConstantCurvatures() const override { return true; }
  [[nodiscard]] double turns() const override { return turns_; }
  [[nodiscard]] std::string describe() const override;
  [[nodiscard]] double radius() const { return radius_; }
  [[nodiscard]] const Vec3& centre() const { return centre_; }

 private:
  std::shared_ptr<const Plane> plane_;
  Vec3 centre_, e1_, e2_;
  double radius_, turns_, sense_;
};

class SphereParallelPath final : public ContactPath {
 public:
  // Parallel at colatitude θ ∈ (0, π), starting at azimuth startAzimuth
  // (radians, default 0), moving counter-clockwise about +z (seen from above
  // the north pole) when counterClockwise: φ(s) = φ0 ± s/ρ.
  SphereParallelPath(std::shared_ptr<const Sphere> sphere, double colatitude, double turns, bool counterClockwise,
                     double startAzimuth = 0.0);
  [[nodiscard]] double length() const override;
  [[nodiscard]] DarbouxSample at(double s) const override;
  [[nodiscard]] Vec3 point(double s) const override;
  [[nodiscard]] Vec3 normal(double s) const override;
  [[nodiscard]] bool hasConstantCurvatures() const override { return true; }
  [[nodiscard]] double turns() const override { return turns_; }
  [[nodiscard]] std::string describe() const override;
  [[nodiscard]] double parallelRadius() const;  // ρ = r sin θ

 private:
  [[nodiscard]] double azimuth(double s) const;
  std::shared_ptr<const Sphere> sphere_;
  double colatitude_, turns_, sense_, startAzimuth_;
};

}  // namespace rollspin::geometry
