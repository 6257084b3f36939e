// ScreenAxes — a camera's right and up directions and the tangents of its
// half angles across them, for orbit angles and a lens: a point p seen
// with target t and distance D lies at NDC ((p − t)·axes[i]) /
// (tans[i] (D − (p − t)·toEye)) on axis i. Shared by the framing's files.
#pragma once

#include <cmath>

#include "draw/camera_framing.hpp"
#include "draw/draw_style.hpp"

namespace rollspin::draw {

struct ScreenAxes {
  geometry::Vec3 toEye;
  geometry::Vec3 axes[2];
  double tans[2];
};

inline ScreenAxes screenAxes(const OrbitAngles &a, double fovDeg, double aspect) {
  const geometry::Vec3 toEye = towardEye(a);
  const geometry::Vec3 right = geometry::Vec3::UnitZ().cross(toEye).normalized();
  const double tanV = std::tan(0.5 * fovDeg * kDeg);
  return {toEye, {right, toEye.cross(right)}, {tanV * aspect, tanV}};
}

}  // namespace rollspin::draw
