#include "geometry/contact_path.hpp"

#include <cstdio>

namespace rollspin::geometry {

Vec3 darbouxVector(const DarbouxSample& f) {
  return f.geodesicTorsion * f.tangent - f.normalCurvature * f.tangentNormal + f.geodesicCurvature * f.normal;
}

std::string describeNumber(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

std::string describeTurns(double turns) { return describeNumber(turns) + (turns == 1.0 ? " turn" : " turns"); }

Vec3 defaultTangentFor(const Vec3& n) {
  const Vec3 unitN = n.normalized();
  const Vec3 horizontal = Vec3::UnitZ().cross(unitN);
  // |ẑ × n| = sin of the tilt; below ~1e-8 the plane counts as horizontal.
  if (horizontal.norm() > 1e-8) return horizontal.normalized();
  return Vec3::UnitX();
}

}  // namespace rollspin::geometry
