// Test helpers shared by the suites: building a contact path straight from
// geometry (no scene file), and comparing orientations.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <memory>

#include "geometry/analytic_paths.hpp"

namespace rollspin::test {

std::unique_ptr<geometry::ContactPath> lollipopPath(double circleRadius, double turns = 1.0, bool ccw = true);
std::unique_ptr<geometry::ContactPath> planeLine(const Eigen::Vector3d& normal, double length);
std::unique_ptr<geometry::ContactPath> sphereParallel(double sphereRadius, bool outside, double colatitude,
                                                      double turns = 1.0, bool ccw = true);

// Rotation angle of AᵀB for rotation matrices (SO(3) distance), via atan2.
double rotationMatrixDistance(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b);

}  // namespace rollspin::test
