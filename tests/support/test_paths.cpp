#include "support/test_paths.hpp"

#include <cmath>

namespace rollspin::test {

std::unique_ptr<geometry::ContactPath> lollipopPath(double circleRadius, double turns, bool ccw) {
  auto plane = std::make_shared<const geometry::Plane>(Eigen::Vector3d::UnitZ());
  return std::make_unique<geometry::PlaneCirclePath>(plane, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(),
                                                     circleRadius, turns, ccw);
}

std::unique_ptr<geometry::ContactPath> planeLine(const Eigen::Vector3d& normal, double length) {
  auto plane = std::make_shared<const geometry::Plane>(normal);
  return std::make_unique<geometry::PlaneLinePath>(plane, Eigen::Vector3d::Zero(),
                                                   geometry::defaultTangentFor(plane->normal()), length);
}

std::unique_ptr<geometry::ContactPath> sphereParallel(double sphereRadius, bool outside, double colatitude,
                                                      double turns, bool ccw) {
  auto sphere = std::make_shared<const geometry::Sphere>(sphereRadius,
                                                         outside ? geometry::Side::Outside : geometry::Side::Inside);
  return std::make_unique<geometry::SphereParallelPath>(sphere, colatitude, turns, ccw);
}

double rotationMatrixDistance(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  const Eigen::Matrix3d d = a.transpose() * b;
  const Eigen::Vector3d axisTimesSin(d(2, 1) - d(1, 2), d(0, 2) - d(2, 0), d(1, 0) - d(0, 1));
  return std::atan2(0.5 * axisTimesSin.norm(), 0.5 * (d.trace() - 1.0));
}

}  // namespace rollspin::test
