#include "geometry/surface.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>
#include <string>

#include "geometry/contact_path.hpp"
#include "geometry/jet.hpp"

namespace rollspin::geometry {

Vec3 Surface::normal(const Vec2& uv) const {
  const SurfaceJet j = jet(uv);
  return orientation() * j.xu.cross(j.xv).normalized();
}

SurfaceShape shapeFromJet(const SurfaceJet& j, double orientation) {
  SurfaceShape sh;
  sh.point = j.x;
  sh.normal = orientation * j.xu.cross(j.xv).normalized();
  sh.E = j.xu.dot(j.xu);
  sh.F = j.xu.dot(j.xv);
  sh.G = j.xv.dot(j.xv);
  sh.L = j.xuu.dot(sh.normal);
  sh.M = j.xuv.dot(sh.normal);
  sh.N = j.xvv.dot(sh.normal);
  const double det = sh.E * sh.G - sh.F * sh.F;
  sh.meanCurvature = (sh.E * sh.N - 2.0 * sh.F * sh.M + sh.G * sh.L) / (2.0 * det);
  sh.gaussCurvature = (sh.L * sh.N - sh.M * sh.M) / det;
  // H² − K = ((k1 − k2)/2)² ≥ 0; clamp the round-off below zero at umbilics.
  const double half = std::sqrt(std::max(0.0, sh.meanCurvature * sh.meanCurvature - sh.gaussCurvature));
  sh.maxCurvature = sh.meanCurvature + half;
  sh.minCurvature = sh.meanCurvature - half;
  return sh;
}

SurfaceShape shapeAt(const Surface& surface, const Vec2& uv) {
  return shapeFromJet(surface.jet(uv), surface.orientation());
}

// ---- plane ---------------------------------------------------------------

Plane::Plane(const Vec3& normal) : normal_(normal.normalized()) {
  assert(normal.norm() > 0.0);
  e1_ = defaultTangentFor(normal_);
  e2_ = normal_.cross(e1_);
}

SurfaceJet Plane::jet(const Vec2& uv) const {
  SurfaceJet j;
  j.x = uv.x() * e1_ + uv.y() * e2_;
  j.xu = e1_;
  j.xv = e2_;
  return j;
}

std::optional<Vec2> Plane::parametersOf(const Vec3& point) const { return Vec2(point.dot(e1_), point.dot(e2_)); }

std::string Plane::parameterNames() const { return "(u, v): coordinates along e1 = ẑ × n (or x̂) and e2 = n × e1"; }

Vec3 Plane::normalAt(const Vec3& /*point*/) const { return normal_; }

SurfaceLook Plane::look() const {
  return {.mesh = SurfaceLook::Mesh::Board, .up = normal_, .orientedByUp = true, .canHideBall = false};
}

double Plane::distance(const Vec3& point) const { return normal_.dot(point); }

std::string Plane::describe() const {
  return "plane with normal (" + std::to_string(normal_.x()) + ", " + std::to_string(normal_.y()) + ", " +
         std::to_string(normal_.z()) + ")";
}

// ---- sphere --------------------------------------------------------------

Sphere::Sphere(double radius, Side side) : radius_(radius), side_(side) { assert(radius > 0.0); }

SurfaceJet Sphere::jet(const Vec2& uv) const {
  const double st = std::sin(uv.x()), ct = std::cos(uv.x()), sp = std::sin(uv.y()), cp = std::cos(uv.y());
  const double r = radius_;
  SurfaceJet j;
  j.x = r * Vec3(st * cp, st * sp, ct);
  j.xu = r * Vec3(ct * cp, ct * sp, -st);
  j.xv = r * Vec3(-st * sp, st * cp, 0.0);
  j.xuu = -j.x;
  j.xuv = r * Vec3(-ct * sp, ct * cp, 0.0);
  j.xvv = r * Vec3(-st * cp, -st * sp, 0.0);
  return j;
}

ParameterDomain Sphere::domain() const {
  ParameterDomain d;
  d.uMin = 0.0;
  d.uMax = std::numbers::pi;
  return d;
}

std::optional<Vec2> Sphere::parametersOf(const Vec3& point) const {
  const double rho = std::hypot(point.x(), point.y());
  if (rho == 0.0) return std::nullopt;  // a pole: azimuth undefined
  return Vec2(std::atan2(rho, point.z()), std::atan2(point.y(), point.x()));
}

std::string Sphere::parameterNames() const { return "(θ, φ): colatitude and azimuth in radians"; }

Vec3 Sphere::normalAt(const Vec3& point) const { return sideSign() * point.normalized(); }

double Sphere::distance(const Vec3& point) const { return point.norm() - radius_; }

std::string Sphere::describe() const {
  return std::string("sphere of radius ") + std::to_string(radius_) +
         (side_ == Side::Outside ? " (outside)" : " (inside)");
}

Vec3 Sphere::defaultStart() const {
  constexpr double kSixtyDegrees = 60.0 * (std::numbers::pi / 180.0);
  return Vec3(radius_ * Vec3(std::sin(kSixtyDegrees), 0.0, std::cos(kSixtyDegrees)));
}

SurfaceLook Sphere::look() const {
  return {.mesh = SurfaceLook::Mesh::Sphere, .radius = radius_, .cutAwayTowardEye = side_ == Side::Inside};
}

}  // namespace rollspin::geometry
