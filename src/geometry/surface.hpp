// Surface — the rigid surface the ball rolls on. Its only duty towards the
// rolling constraint is the unit normal on the ball's side at a surface point;
// the independent kinematic oracle reads n(s) through here, never through the
// closed-form Darboux frame of a path.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>

namespace rollspin::geometry {

using Vec3 = Eigen::Vector3d;

class Surface {
 public:
  virtual ~Surface() = default;
  // Unit normal at a point on the surface, pointing to the ball's side.
  [[nodiscard]] virtual Vec3 normalAt(const Vec3& point) const = 0;
  // Signed distance of a point from the surface (0 on it); used to check
  // that a path stays on the surface.
  [[nodiscard]] virtual double distance(const Vec3& point) const = 0;
  [[nodiscard]] virtual std::string describe() const = 0;
};

// Plane through the origin with unit normal `normal` (the ball's side).
class Plane final : public Surface {
 public:
  explicit Plane(const Vec3& normal);
  [[nodiscard]] Vec3 normalAt(const Vec3& point) const override;
  [[nodiscard]] double distance(const Vec3& point) const override;
  [[nodiscard]] std::string describe() const override;
  [[nodiscard]] const Vec3& normal() const { return normal_; }

 private:
  Vec3 normal_;
};

enum class Side { Outside, Inside };

// Sphere of radius r centred at the origin; the ball rolls on its outside
// (n = P/r) or inside (n = −P/r).
class Sphere final : public Surface {
 public:
  Sphere(double radius, Side side);
  [[nodiscard]] Vec3 normalAt(const Vec3& point) const override;
  [[nodiscard]] double distance(const Vec3& point) const override;
  [[nodiscard]] std::string describe() const override;
  [[nodiscard]] double radius() const { return radius_; }
  [[nodiscard]] Side side() const { return side_; }
  // +1 outside, −1 inside: n = sideSign · P / r.
  [[nodiscard]] double sideSign() const { return side_ == Side::Outside ? 1.0 : -1.0; }

 private:
  double radius_;
  Side side_;
};

}  // namespace rollspin::geometry
