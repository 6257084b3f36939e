#include "scene/path_kinds.hpp"

#include "scene/scene_tables.hpp"

#include <algorithm>
#include <cassert>

namespace rollspin::scene {

namespace {
using S = SurfaceKind;
const std::vector<PathKindRow>& pathTable() {
  static const std::vector<PathKindRow> rows{
      {PathKind::Line,
       "line",
       LiesOn::Plane,
       {{std::string(key::kLength), {}}, {std::string(key::kDirectionVector), {}}}},
      {PathKind::Circle,
       "circle",
       LiesOn::Plane,
       {{std::string(key::kTurns), {}}, {std::string(key::kDirection), {}}, {std::string(key::kRadius), {}}}},
      {PathKind::Parallel,
       "parallel",
       LiesOn::Revolution,
       {{std::string(key::kTurns), {}},
        {std::string(key::kDirection), {}},
        {std::string(key::kStartAzimuthDeg), {}},
        {std::string(key::kRadius), {S::Paraboloid}},
        {std::string(key::kColatitudeDeg), {S::Sphere}},
        {std::string(key::kTubeAngleDeg), {S::Torus}},
        {std::string(key::kHeight), {S::Cylinder}}}},
      {PathKind::Meridian,
       "meridian",
       LiesOn::Curved,
       {{std::string(key::kTurns), {S::Torus}},
        {std::string(key::kDirection), {S::Torus}},
        {std::string(key::kLength), {S::Cylinder, S::Paraboloid, S::Saddle, S::Height}},
        {std::string(key::kTubeAngleDeg), {S::Torus}},
        {std::string(key::kHeight), {S::Cylinder}},
        {std::string(key::kAzimuthDeg), {}},
        {std::string(key::kColatitudeStartDeg), {S::Sphere}},
        {std::string(key::kColatitudeEndDeg), {S::Sphere}}}},
      {PathKind::Helix,
       "helix",
       LiesOn::Cylinder,
       {{std::string(key::kTurns), {}},
        {std::string(key::kDirection), {}},
        {std::string(key::kHeight), {}},
        {std::string(key::kPitchAngleDeg), {}}}},
      {PathKind::Loxodrome,
       "loxodrome",
       LiesOn::Sphere,
       {{std::string(key::kAzimuthDeg), {}},
        {std::string(key::kColatitudeStartDeg), {}},
        {std::string(key::kColatitudeEndDeg), {}},
        {std::string(key::kHeadingDeg), {}}}},
      {PathKind::Geodesic,
       "geodesic",
       LiesOn::Any,
       {{std::string(key::kLength), {}},
        {std::string(key::kDirectionVector), {}},
        {std::string(key::kStartPoint), {}}}},
      {PathKind::Uv,
       "uv",
       LiesOn::Any,
       {{std::string(key::kU), {}},
        {std::string(key::kV), {}},
        {std::string(key::kTStart), {}},
        {std::string(key::kTEnd), {}}}},
      {PathKind::Points,
       "points",
       LiesOn::Any,
       {{std::string(key::kPoints), {}},
        {std::string(key::kClosed), {}},
        {std::string(key::kInterpolation), {}},
        {std::string(key::kCornerRadius), {}}}},
      {PathKind::Clothoid,
       "clothoid",
       LiesOn::Plane,
       {{std::string(key::kLength), {}},
        {std::string(key::kDirectionVector), {}},
        {std::string(key::kCurvatureStart), {}},
        {std::string(key::kCurvatureRate), {}}}},
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
    case LiesOn::Revolution: return sceneSurfaceKind(surface).ofRevolution;
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
