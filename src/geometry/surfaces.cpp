#include "geometry/surfaces.hpp"

#include <array>
#include <cmath>
#include <numbers>

#include "geometry/contact_path.hpp"

namespace rollspin::geometry {

namespace {

// Evaluates a point function p(u, v) (three Jets) with u, v as the Jet's two
// variables and unpacks the derivatives.
template <typename F>
SurfaceJet jetOf(const F& p, const Vec2& uv) {
  const std::array<Jet, 3> x = p(Jet::variableA(uv.x()), Jet::variableB(uv.y()));
  SurfaceJet j;
  for (int i = 0; i < 3; ++i) {
    j.x[i] = x[i].v;
    j.xu[i] = x[i].da;
    j.xv[i] = x[i].db;
    j.xuu[i] = x[i].daa;
    j.xuv[i] = x[i].dab;
    j.xvv[i] = x[i].dbb;
  }
  return j;
}

}  // namespace

// ---- cylinder --------------------------------------------------------------

Cylinder::Cylinder(double radius, const Vec3& axis, Side side)
    : radius_(radius), axis_(axis.normalized()), side_(side) {
  // e1, e2, d right-handed, so x_φ × x_z points away from the axis.
  e1_ = defaultTangentFor(axis_);
  if (std::abs(e1_.dot(axis_)) > 0.5) e1_ = Vec3::UnitX();
  e1_ = (e1_ - e1_.dot(axis_) * axis_).normalized();
  e2_ = axis_.cross(e1_);
}

SurfaceJet Cylinder::jet(const Vec2& uv) const {
  return jetOf(
      [this](const Jet& phi, const Jet& z) {
        const Jet c = cos(phi), s = sin(phi);
        std::array<Jet, 3> x;
        for (int i = 0; i < 3; ++i) x[i] = radius_ * (c * e1_[i] + s * e2_[i]) + z * axis_[i];
        return x;
      },
      uv);
}

std::optional<Vec2> Cylinder::parametersOf(const Vec3& point) const {
  const double a = point.dot(e1_), b = point.dot(e2_);
  if (a == 0.0 && b == 0.0) return std::nullopt;
  return Vec2(std::atan2(b, a), point.dot(axis_));
}

// φ is an angle: the chart repeats every 2π around the axis.
ParameterDomain Cylinder::domain() const {
  ParameterDomain d;
  d.uPeriod = 2.0 * std::numbers::pi;
  return d;
}

Vec3 Cylinder::normalAt(const Vec3& point) const {
  const Vec3 radial = point - point.dot(axis_) * axis_;
  return orientation() * radial.normalized();
}

double Cylinder::distance(const Vec3& point) const { return (point - point.dot(axis_) * axis_).norm() - radius_; }

std::string Cylinder::describe() const {
  return "cylinder of radius " + describeNumber(radius_) + " about (" + describeNumber(axis_.x()) + ", " +
         describeNumber(axis_.y()) + ", " + describeNumber(axis_.z()) + ")" +
         (side_ == Side::Outside ? " (outside)" : " (inside)");
}

std::string Cylinder::parameterNames() const { return "(φ, z): azimuth in radians about the axis and height along it"; }

// ---- torus -----------------------------------------------------------------

Torus::Torus(double majorRadius, double minorRadius, Side side)
    : major_(majorRadius), minor_(minorRadius), side_(side) {}

SurfaceJet Torus::jet(const Vec2& uv) const {
  return jetOf(
      [this](const Jet& phi, const Jet& psi) {
        const Jet ring = major_ + minor_ * cos(psi);
        return std::array<Jet, 3>{ring * cos(phi), ring * sin(phi), minor_ * sin(psi)};
      },
      uv);
}

std::optional<Vec2> Torus::parametersOf(const Vec3& point) const {
  const double rho = std::hypot(point.x(), point.y());
  if (rho == 0.0) return std::nullopt;
  return Vec2(std::atan2(point.y(), point.x()), std::atan2(point.z(), rho - major_));
}

// φ and ψ are both angles.
ParameterDomain Torus::domain() const {
  ParameterDomain d;
  d.uPeriod = d.vPeriod = 2.0 * std::numbers::pi;
  return d;
}

Vec3 Torus::normalAt(const Vec3& point) const {
  const double rho = std::hypot(point.x(), point.y());
  const Vec3 ringPoint = (major_ / rho) * Vec3(point.x(), point.y(), 0.0);
  return orientation() * (point - ringPoint).normalized();
}

double Torus::distance(const Vec3& point) const {
  return std::hypot(std::hypot(point.x(), point.y()) - major_, point.z()) - minor_;
}

std::string Torus::describe() const {
  return "torus with major radius " + describeNumber(major_) + " and tube radius " + describeNumber(minor_) +
         (side_ == Side::Outside ? " (outside)" : " (inside the tube)");
}

std::string Torus::parameterNames() const {
  return "(φ, ψ): angle about ẑ and angle round the tube (0 on the outer equator), radians";
}

// ---- height fields ---------------------------------------------------------

HeightField::HeightField(Function f, bool ballAbove, std::string description)
    : f_(std::move(f)), ballAbove_(ballAbove), description_(std::move(description)) {}

std::shared_ptr<HeightField> HeightField::quadric(double a, double b, bool saddle, bool ballAbove) {
  const double ca = 0.5 / a, cb = (saddle ? -0.5 : 0.5) / b;
  auto surface = std::make_shared<HeightField>(
      [ca, cb](const Jet& x, const Jet& y) { return ca * (x * x) + cb * (y * y); }, ballAbove,
      std::string(saddle ? "saddle" : "paraboloid") + " z = (x²/" + describeNumber(a) + (saddle ? " − " : " + ") +
          "y²/" + describeNumber(b) + ")/2" + (ballAbove ? " (above)" : " (below)"));
  surface->revolution_ = !saddle && a == b;
  return surface;
}

std::shared_ptr<HeightField> HeightField::fromExpression(std::shared_ptr<const Expression> z, bool ballAbove) {
  const std::string text = z->text();
  return std::make_shared<HeightField>([z](const Jet& x, const Jet& y) { return z->jet(x, y); }, ballAbove,
                                       "height field z = " + text + (ballAbove ? " (above)" : " (below)"));
}

SurfaceJet HeightField::jet(const Vec2& uv) const {
  const Jet z = f_(Jet::variableA(uv.x()), Jet::variableB(uv.y()));
  SurfaceJet j;
  j.x = Vec3(uv.x(), uv.y(), z.v);
  j.xu = Vec3(1.0, 0.0, z.da);
  j.xv = Vec3(0.0, 1.0, z.db);
  j.xuu = Vec3(0.0, 0.0, z.daa);
  j.xuv = Vec3(0.0, 0.0, z.dab);
  j.xvv = Vec3(0.0, 0.0, z.dbb);
  return j;
}

Vec3 HeightField::position(const Vec2& uv) const { return {uv.x(), uv.y(), f_(Jet(uv.x()), Jet(uv.y())).v}; }

std::optional<Vec2> HeightField::parametersOf(const Vec3& point) const { return Vec2(point.x(), point.y()); }

Vec3 HeightField::normalAt(const Vec3& point) const { return normal(Vec2(point.x(), point.y())); }

double HeightField::distance(const Vec3& point) const { return point.z() - f_(Jet(point.x()), Jet(point.y())).v; }

std::string HeightField::parameterNames() const { return "(x, y): the horizontal coordinates"; }

}  // namespace rollspin::geometry
