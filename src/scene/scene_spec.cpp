#include "scene/scene_spec.hpp"

#include <cmath>

namespace rollspin::scene {

KeyRule surfaceKeyRule(const std::string& key, SurfaceKind sk) {
  if (key == "normal") return {sk == SurfaceKind::Plane, "\"plane\""};
  if (key == "radius") return {sk == SurfaceKind::Sphere || sk == SurfaceKind::Cylinder, "\"sphere\" or \"cylinder\""};
  if (key == "side")
    return {sk != SurfaceKind::Plane, "sphere, cylinder, torus (outside | inside) or a height field (above | below)"};
  if (key == "axis") return {sk == SurfaceKind::Cylinder, "\"cylinder\""};
  if (key == "major_radius" || key == "minor_radius") return {sk == SurfaceKind::Torus, "\"torus\""};
  if (key == "a" || key == "b")
    return {sk == SurfaceKind::Paraboloid || sk == SurfaceKind::Saddle, "\"paraboloid\" or \"saddle\""};
  if (key == "z") return {sk == SurfaceKind::Height, "\"height\""};
  return {true, ""};
}

KeyRule pathKeyRule(const std::string& key, PathKind pk, SurfaceKind sk) {
  const bool onSphere = sk == SurfaceKind::Sphere, onTorus = sk == SurfaceKind::Torus,
             onCylinder = sk == SurfaceKind::Cylinder;
  const bool meridian = pk == PathKind::Meridian, parallel = pk == PathKind::Parallel;
  if (key == "turns" || key == "direction")
    return {pk == PathKind::Circle || parallel || pk == PathKind::Helix || (meridian && onTorus),
            "circle or parallel (or helix, or meridian on a torus)"};
  const bool clothoid = pk == PathKind::Clothoid;
  if (key == "length")
    return {pk == PathKind::Line || pk == PathKind::Geodesic || clothoid || (meridian && !onSphere && !onTorus),
            "line, clothoid, geodesic or meridian on a cylinder or height field"};
  if (key == "direction_vector")
    return {pk == PathKind::Line || pk == PathKind::Geodesic || clothoid, "line, clothoid or geodesic"};
  if (key == "curvature_start" || key == "curvature_rate") return {clothoid, "clothoid"};
  if (key == "radius")
    return {pk == PathKind::Circle || (parallel && sk == SurfaceKind::Paraboloid), "circle or parallel on a paraboloid"};
  if (key == "colatitude_deg") return {parallel && onSphere, "parallel on a sphere"};
  if (key == "tube_angle_deg") return {(parallel || meridian) && onTorus, "parallel or meridian on a torus"};
  if (key == "height")
    return {(parallel || meridian || pk == PathKind::Helix) && onCylinder, "parallel, meridian or helix on a cylinder"};
  if (key == "azimuth_deg") return {meridian || pk == PathKind::Loxodrome, "meridian or loxodrome"};
  if (key == "colatitude_start_deg" || key == "colatitude_end_deg")
    return {(meridian && onSphere) || pk == PathKind::Loxodrome, "meridian on a sphere or loxodrome"};
  if (key == "pitch_angle_deg") return {pk == PathKind::Helix, "helix"};
  if (key == "heading_deg") return {pk == PathKind::Loxodrome, "loxodrome"};
  if (key == "start_point") return {pk == PathKind::Geodesic, "geodesic"};
  if (key == "u" || key == "v" || key == "t_start" || key == "t_end") return {pk == PathKind::Uv, "uv"};
  if (key == "points" || key == "closed" || key == "interpolation" || key == "corner_radius")
    return {pk == PathKind::Points, "points"};
  return {true, ""};
}

SourceLoc SceneSpec::where(const std::string& key) const {
  if (auto it = locations.find(key); it != locations.end()) return it->second;
  return SourceLoc{sourceFile.empty() ? std::string("<scene>") : sourceFile};
}

std::string toString(SurfaceKind k) {
  switch (k) {
    case SurfaceKind::Plane: return "plane";
    case SurfaceKind::Sphere: return "sphere";
    case SurfaceKind::Cylinder: return "cylinder";
    case SurfaceKind::Torus: return "torus";
    case SurfaceKind::Paraboloid: return "paraboloid";
    case SurfaceKind::Saddle: return "saddle";
    case SurfaceKind::Height: return "height";
  }
  return "?";
}

std::string toString(PathKind k) {
  switch (k) {
    case PathKind::Line: return "line";
    case PathKind::Circle: return "circle";
    case PathKind::Parallel: return "parallel";
    case PathKind::Meridian: return "meridian";
    case PathKind::Helix: return "helix";
    case PathKind::Loxodrome: return "loxodrome";
    case PathKind::Geodesic: return "geodesic";
    case PathKind::Uv: return "uv";
    case PathKind::Points: return "points";
    case PathKind::Clothoid: return "clothoid";
  }
  return "?";
}

std::string toString(RenderLayout l) {
  switch (l) {
    case RenderLayout::SideBySide: return "side-by-side";
    case RenderLayout::Inset: return "inset";
    case RenderLayout::Ball: return "ball";
    case RenderLayout::Twin: return "twin";
  }
  return "?";
}

std::string toString(Fact f) { return kFactNames[static_cast<std::size_t>(f)]; }

namespace {
bool wholeTurns(double turns) { return std::abs(turns - std::round(turns)) < 1e-9; }
bool planeCircle(const SceneSpec& s) { return s.surface.kind == SurfaceKind::Plane && s.path.kind == PathKind::Circle; }
bool sphereParallel(const SceneSpec& s) {
  return s.surface.kind == SurfaceKind::Sphere && s.path.kind == PathKind::Parallel;
}
bool onEquator(const SceneSpec& s) { return std::abs(s.path.colatitudeDeg - 90.0) < 1e-9; }
}  // namespace

KeyRule factRule(Fact f, const SceneSpec& spec) {
  // A storyboard's facts are its captions: the closed forms are about one path.
  if (spec.isStoryboard()) return {false, "a scene with one [path] (a storyboard's segments have captions)"};
  switch (f) {
    case Fact::Delta: return {planeCircle(spec) || sphereParallel(spec), "a circle on a plane or a parallel on a sphere"};
    case Fact::Marks: return {planeCircle(spec), "a circle on a plane"};
    case Fact::Turns: return {sphereParallel(spec) && onEquator(spec), "a parallel on a sphere at colatitude_deg = 90"};
    case Fact::PhaseSplit:
      return {(planeCircle(spec) || sphereParallel(spec)) && wholeTurns(spec.path.turns),
              "a circle on a plane or a parallel on a sphere, with whole path.turns (B's loop must close)"};
  }
  return {false, ""};
}

std::vector<Fact> resolveFacts(const SceneSpec& spec) {
  if (spec.labels.facts) return *spec.labels.facts;
  if (spec.isStoryboard()) return {};
  if (spec.plate) return {Fact::Marks};
  if (planeCircle(spec)) return {Fact::Delta};
  if (sphereParallel(spec)) {
    if (onEquator(spec)) return {Fact::Turns};
    if (spec.ball.radius <= 0.1 * spec.surface.radius && wholeTurns(spec.path.turns)) return {Fact::PhaseSplit};
    return {Fact::Delta};
  }
  return {};
}

}  // namespace rollspin::scene
