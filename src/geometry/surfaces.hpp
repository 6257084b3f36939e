// Curved surfaces beyond the plane and the sphere, each a parametrised
// surface x(u, v) with exact derivatives (written once over Jet numbers):
//   Cylinder  x(φ, z) = a (cos φ e1 + sin φ e2) + z d          (axis d, radius a)
//   Torus     x(φ, ψ) = (A + a cos ψ)(cos φ, sin φ, 0) + a sin ψ ẑ
//             (major radius A about ẑ, tube radius a, ψ = 0 on the outer equator)
//   HeightField  x(x, y) = (x, y, f(x, y)), with f a quadric
//             (x²/a ± y²/b)/2 (paraboloid / saddle) or an Expression.
// Side: Outside puts the ball on the side of x_u × x_v (away from the axis for
// the cylinder, out of the tube for the torus, above for a height field).
#pragma once

#include <functional>
#include <memory>

#include "geometry/expression.hpp"
#include "geometry/jet.hpp"
#include "geometry/surface.hpp"

namespace rollspin::geometry {

class Cylinder final : public Surface {
 public:
  // axis: direction of the cylinder's axis through the origin (normalised).
  Cylinder(double radius, const Vec3& axis, Side side);
  [[nodiscard]] Vec3 normalAt(const Vec3& point) const override;
  [[nodiscard]] double distance(const Vec3& point) const override;
  [[nodiscard]] std::string describe() const override;
  [[nodiscard]] SurfaceJet jet(const Vec2& uv) const override;
  [[nodiscard]] double orientation() const override { return side_ == Side::Outside ? 1.0 : -1.0; }
  [[nodiscard]] std::optional<Vec2> parametersOf(const Vec3& point) const override;
  [[nodiscard]] std::string parameterNames() const override;
  [[nodiscard]] ParameterDomain domain() const override;
  [[nodiscard]] double radius() const { return radius_; }
  [[nodiscard]] Side side() const { return side_; }

 private:
  double radius_;
  Vec3 axis_, e1_, e2_;
  Side side_;
};

class Torus final : public Surface {
 public:
  Torus(double majorRadius, double minorRadius, Side side);
  [[nodiscard]] Vec3 normalAt(const Vec3& point) const override;
  [[nodiscard]] double distance(const Vec3& point) const override;
  [[nodiscard]] std::string describe() const override;
  [[nodiscard]] SurfaceJet jet(const Vec2& uv) const override;
  [[nodiscard]] double orientation() const override { return side_ == Side::Outside ? 1.0 : -1.0; }
  [[nodiscard]] std::optional<Vec2> parametersOf(const Vec3& point) const override;
  [[nodiscard]] std::string parameterNames() const override;
  [[nodiscard]] ParameterDomain domain() const override;
  // (A + a, 0, 0), the outer equator at φ = 0.
  [[nodiscard]] Vec3 defaultStart() const override { return Vec3(major_ + minor_, 0.0, 0.0); }
  [[nodiscard]] double majorRadius() const { return major_; }
  [[nodiscard]] double minorRadius() const { return minor_; }

 private:
  double major_, minor_;
  Side side_;
};

// z = f(x, y); f and its derivatives come from a Jet function.
class HeightField final : public Surface {
 public:
  using Function = std::function<Jet(const Jet& x, const Jet& y)>;
  // ballAbove: the ball rolls on the upper side (n·ẑ > 0).
  HeightField(Function f, bool ballAbove, std::string description);
  // z = (x²/a + sy y²/b)/2 with sy = +1 (paraboloid) or −1 (saddle).
  static std::shared_ptr<HeightField> quadric(double a, double b, bool saddle, bool ballAbove);
  // z = expression in x and y.
  static std::shared_ptr<HeightField> fromExpression(std::shared_ptr<const Expression> z, bool ballAbove);

  [[nodiscard]] Vec3 normalAt(const Vec3& point) const override;
  [[nodiscard]] double distance(const Vec3& point) const override;
  [[nodiscard]] std::string describe() const override { return description_; }
  [[nodiscard]] SurfaceJet jet(const Vec2& uv) const override;
  [[nodiscard]] Vec3 position(const Vec2& uv) const override;
  [[nodiscard]] double orientation() const override { return ballAbove_ ? 1.0 : -1.0; }
  [[nodiscard]] std::optional<Vec2> parametersOf(const Vec3& point) const override;
  [[nodiscard]] std::string parameterNames() const override;
  // Rotationally symmetric about ẑ (a paraboloid with a = b, or flat).
  [[nodiscard]] bool isRevolution() const { return revolution_; }

 private:
  Function f_;
  bool ballAbove_;
  std::string description_;
  bool revolution_ = false;
};

}  // namespace rollspin::geometry
