#include "geometry/analytic_paths.hpp"

#include <cassert>
#include <cmath>
#include <numbers>
#include <string>

namespace rollspin::geometry {

// ---- line --------------------------------------------------------------

PlaneLinePath::PlaneLinePath(std::shared_ptr<const Plane> plane, const Vec3& start, const Vec3& direction,
                             double length)
    : plane_(std::move(plane)), start_(start), direction_(direction.normalized()), length_(length) {
  assert(std::abs(direction_.dot(plane_->normal())) < 1e-12);
}

Vec3 PlaneLinePath::point(double s) const { return start_ + s * direction_; }

Vec3 PlaneLinePath::normal(double s) const { return plane_->normalAt(point(s)); }

DarbouxSample PlaneLinePath::at(double s) const {
  DarbouxSample f;
  f.s = s;
  f.point = point(s);
  f.tangent = direction_;
  f.normal = plane_->normal();
  f.tangentNormal = f.normal.cross(f.tangent);
  return f;
}

std::string PlaneLinePath::describe() const {
  return "line of length " + describeNumber(length_) + " on a " + plane_->describe();
}

// ---- circle on a plane -------------------------------------------------

PlaneCirclePath::PlaneCirclePath(std::shared_ptr<const Plane> plane, const Vec3& centre, const Vec3& e1, double radius,
                                 double turns, bool counterClockwise)
    : plane_(std::move(plane)),
      centre_(centre),
      e1_(e1.normalized()),
      e2_(plane_->normal().cross(e1_)),
      radius_(radius),
      turns_(turns),
      sense_(counterClockwise ? 1.0 : -1.0) {
  assert(radius > 0.0);
  assert(std::abs(e1_.dot(plane_->normal())) < 1e-12);
}

double PlaneCirclePath::length() const { return 2.0 * std::numbers::pi * radius_ * turns_; }

Vec3 PlaneCirclePath::point(double s) const {
  const double phi = sense_ * s / radius_;
  return centre_ + radius_ * (std::cos(phi) * e1_ + std::sin(phi) * e2_);
}

Vec3 PlaneCirclePath::normal(double s) const { return plane_->normalAt(point(s)); }

DarbouxSample PlaneCirclePath::at(double s) const {
  const double phi = sense_ * s / radius_;
  const double c = std::cos(phi), sn = std::sin(phi);
  DarbouxSample f;
  f.s = s;
  f.point = centre_ + radius_ * (c * e1_ + sn * e2_);
  f.tangent = sense_ * (-sn * e1_ + c * e2_);
  f.normal = plane_->normal();
  f.tangentNormal = -sense_ * (c * e1_ + sn * e2_);  // n × t
  f.geodesicCurvature = sense_ / radius_;
  return f;
}

std::string PlaneCirclePath::describe() const {
  return "circle of radius " + describeNumber(radius_) + " (" + describeTurns(turns_) + ", " +
         (sense_ > 0 ? "ccw" : "cw") + ") on a " + plane_->describe();
}

// ---- parallel on a sphere ----------------------------------------------

SphereParallelPath::SphereParallelPath(std::shared_ptr<const Sphere> sphere, double colatitude, double turns,
                                       bool counterClockwise, double startAzimuth)
    : sphere_(std::move(sphere)),
      colatitude_(colatitude),
      turns_(turns),
      sense_(counterClockwise ? 1.0 : -1.0),
      startAzimuth_(startAzimuth) {
  assert(colatitude > 0.0 && colatitude < std::numbers::pi);
}

double SphereParallelPath::parallelRadius() const { return sphere_->radius() * std::sin(colatitude_); }

double SphereParallelPath::length() const { return 2.0 * std::numbers::pi * parallelRadius() * turns_; }

// A zero start adds nothing, so scenes without start_azimuth_deg keep their
// bytes (0 + −0 is +0).
double SphereParallelPath::azimuth(double s) const {
  const double swept = sense_ * s / parallelRadius();
  return startAzimuth_ == 0.0 ? swept : startAzimuth_ + swept;
}

Vec3 SphereParallelPath::point(double s) const {
  const double r = sphere_->radius(), phi = azimuth(s);
  const double st = std::sin(colatitude_), ct = std::cos(colatitude_);
  return r * Vec3(st * std::cos(phi), st * std::sin(phi), ct);
}

Vec3 SphereParallelPath::normal(double s) const { return sphere_->normalAt(point(s)); }

DarbouxSample SphereParallelPath::at(double s) const {
  const double r = sphere_->radius(), phi = azimuth(s), side = sphere_->sideSign();
  const double st = std::sin(colatitude_), ct = std::cos(colatitude_);
  const double cp = std::cos(phi), sp = std::sin(phi);
  const Vec3 eR(st * cp, st * sp, ct), ePhi(-sp, cp, 0.0), eTheta(ct * cp, ct * sp, -st);
  DarbouxSample f;
  f.s = s;
  f.point = r * eR;
  f.tangent = sense_ * ePhi;
  f.normal = side * eR;
  f.tangentNormal = -side * sense_ * eTheta;  // n × t, since e_r × e_φ = −e_θ
  f.normalCurvature = -side / r;
  f.geodesicCurvature = side * sense_ * (ct / st) / r;
  return f;
}

std::string SphereParallelPath::describe() const {
  const std::string from =
      startAzimuth_ == 0.0 ? "" : " from azimuth " + describeNumber(startAzimuth_ * 180.0 / std::numbers::pi) + " deg";
  return "parallel at colatitude " + describeNumber(colatitude_ * 180.0 / std::numbers::pi) + " deg" + from + " (" +
         describeTurns(turns_) + ", " + (sense_ > 0 ? "ccw" : "cw") + ") on a " + sphere_->describe();
}

}  // namespace rollspin::geometry
