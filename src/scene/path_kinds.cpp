#include "scene/path_kinds.hpp"

#include <algorithm>
#include <cassert>

namespace rollspin::scene {

namespace {
using S = SurfaceKind;
const std::vector<PathKindRow>& pathTable() {
  static const std::vector<PathKindRow> rows{
      {PathKind::Line, "line", LiesOn::Plane, {{"length", {}}, {"direction_vector", {}}}},
      {PathKind::Circle, "circle", LiesOn::Plane, {{"turns", {}}, {"direction", {}}, {"radius", {}}}},
      {PathKind::Parallel,
       "parallel",
       LiesOn::Revolution,
       {{"turns", {}},
        {"direction", {}},
        {"start_azimuth_deg", {}},
        {"radius", {S::Paraboloid}},
        {"colatitude_deg", {S::Sphere}},
        {"tube_angle_deg", {S::Torus}},
        {"height", {S::Cylinder}}}},
      {PathKind::Meridian,
       "meridian",
       LiesOn::Curved,
       {{"turns", {S::Torus}},
        {"direction", {S::Torus}},
        {"length", {S::Cylinder, S::Paraboloid, S::Saddle, S::Height}},
        {"tube_angle_deg", {S::Torus}},
        {"height", {S::Cylinder}},
        {"azimuth_deg", {}},
        {"colatitude_start_deg", {S::Sphere}},
        {"colatitude_end_deg", {S::Sphere}}}},
      {PathKind::Helix,
       "helix",
       LiesOn::Cylinder,
       {{"turns", {}}, {"direction", {}}, {"height", {}}, {"pitch_angle_deg", {}}}},
      {PathKind::Loxodrome,
       "loxodrome",
       LiesOn::Sphere,
       {{"azimuth_deg", {}}, {"colatitude_start_deg", {}}, {"colatitude_end_deg", {}}, {"heading_deg", {}}}},
      {PathKind::Geodesic, "geodesic", LiesOn::Any, {{"length", {}}, {"direction_vector", {}}, {"start_point", {}}}},
      {PathKind::Uv, "uv", LiesOn::Any, {{"u", {}}, {"v", {}}, {"t_start", {}}, {"t_end", {}}}},
      {PathKind::Points,
       "points",
       LiesOn::Any,
       {{"points", {}}, {"closed", {}}, {"interpolation", {}}, {"corner_radius", {}}}},
      {PathKind::Clothoid,
       "clothoid",
       LiesOn::Plane,
       {{"length", {}}, {"direction_vector", {}}, {"curvature_start", {}}, {"curvature_rate", {}}}},
  };
  return rows;
}
}  // namespace

std::span<const PathKindRow> pathKinds() { return pathTable(); }

const PathKindRow& pathKindRow(PathKind kind) {
  for (const auto& row : pathTable())
    if (row.kind == kind) return row;
  assert(false && "every PathKind has a row");
  return pathTable().front();
}

bool liesOn(PathKind path, SurfaceKind surface) {
  switch (pathKindRow(path).liesOn) {
    case LiesOn::Plane: return surface == SurfaceKind::Plane;
    case LiesOn::Revolution: return surfaceKindRow(surface).ofRevolution;
    case LiesOn::Curved: return surface != SurfaceKind::Plane;
    case LiesOn::Cylinder: return surface == SurfaceKind::Cylinder;
    case LiesOn::Sphere: return surface == SurfaceKind::Sphere;
    case LiesOn::Any: return true;
  }
  return false;
}

std::string describe(LiesOn where) {
  switch (where) {
    case LiesOn::Plane: return "plane";
    case LiesOn::Revolution: {
      std::vector<std::string> names;
      for (const auto& row : surfaceKinds())
        if (row.ofRevolution) names.emplace_back(row.name);
      std::string out;
      for (std::size_t i = 0; i < names.size(); ++i)
        out += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
      return out;
    }
    case LiesOn::Curved: return "curved surface";
    case LiesOn::Cylinder: return "cylinder";
    case LiesOn::Sphere: return "sphere";
    case LiesOn::Any: return "surface";
  }
  return "?";
}

const std::vector<std::string>& allPathKeys() {
  static const std::vector<std::string> keys = [] {
    std::vector<std::string> out;
    for (const auto& row : pathTable())
      for (const auto& k : row.keys)
        if (std::find(out.begin(), out.end(), k.key) == out.end()) out.push_back(k.key);
    return out;
  }();
  return keys;
}

}  // namespace rollspin::scene
