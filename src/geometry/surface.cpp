#include "geometry/surface.hpp"

#include <cassert>
#include <cmath>
#include <string>

namespace rollspin::geometry {

Plane::Plane(const Vec3& normal) : normal_(normal.normalized()) { assert(normal.norm() > 0.0); }

Vec3 Plane::normalAt(const Vec3& /*point*/) const { return normal_; }

double Plane::distance(const Vec3& point) const { return normal_.dot(point); }

std::string Plane::describe() const {
  return "plane with normal (" + std::to_string(normal_.x()) + ", " + std::to_string(normal_.y()) + ", " +
         std::to_string(normal_.z()) + ")";
}

Sphere::Sphere(double radius, Side side) : radius_(radius), side_(side) { assert(radius > 0.0); }

Vec3 Sphere::normalAt(const Vec3& point) const { return sideSign() * point.normalized(); }

double Sphere::distance(const Vec3& point) const { return point.norm() - radius_; }

std::string Sphere::describe() const {
  return std::string("sphere of radius ") + std::to_string(radius_) +
         (side_ == Side::Outside ? " (outside)" : " (inside)");
}

}  // namespace rollspin::geometry
