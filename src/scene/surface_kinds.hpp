// Surface kinds as the scene sees them (SceneSurfaceKind; geometry's own row
// is geometry::SurfaceKindRow, one name per concept): geometry's table
// (geometry/surface_kinds.hpp: each kind's name, its own keys with type,
// default, range, units and meaning, and its factory) with the path a kind
// gets when [path] names none as a PathKind. The loader, the printer and the
// messages read this; a new kind adds no line here (its row is geometry's).
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/surface_kinds.hpp"

namespace rollspin::scene {

// A surface kind is the name of its row. Not an enum, so that a new kind
// needs no line in this header: the constants below are only the kinds that
// code outside the two tables names.
class SurfaceKind {
 public:
  constexpr SurfaceKind() = default;  // a plane
  constexpr explicit SurfaceKind(std::string_view name) : name_(name) {}
  [[nodiscard]] constexpr std::string_view name() const { return name_; }
  friend constexpr bool operator==(SurfaceKind a, SurfaceKind b) { return a.name_ == b.name_; }

  static const SurfaceKind Plane, Sphere, Cylinder, Torus, Paraboloid, Saddle, Height;

 private:
  std::string_view name_ = "plane";
};
inline constexpr SurfaceKind SurfaceKind::Plane{"plane"};
inline constexpr SurfaceKind SurfaceKind::Sphere{"sphere"};
inline constexpr SurfaceKind SurfaceKind::Cylinder{"cylinder"};
inline constexpr SurfaceKind SurfaceKind::Torus{"torus"};
inline constexpr SurfaceKind SurfaceKind::Paraboloid{"paraboloid"};
inline constexpr SurfaceKind SurfaceKind::Saddle{"saddle"};
inline constexpr SurfaceKind SurfaceKind::Height{"height"};

enum class PathKind;

struct SceneSurfaceKind {
  SurfaceKind kind;
  std::string_view name;                     // kind.name()
  std::vector<std::string> keys;             // its own keys of [surface] (besides kind)
  bool ofRevolution;                         // parallels lie on it (a paraboloid only when a = b)
  PathKind defaultPath;                      // [path] without a kind
  const geometry::SurfaceKindRow* geometry;  // its keys' declarations and its factory
};

[[nodiscard]] std::span<const SceneSurfaceKind> surfaceKinds();
[[nodiscard]] const SceneSurfaceKind& sceneSurfaceKind(SurfaceKind kind);
// Every kind-specific key of any kind, in the table's order (no duplicates).
[[nodiscard]] const std::vector<std::string>& allSurfaceKeys();
// The declarations (type, default, range, units, meaning) of a kind's own
// keys, e.g. for `rollspin keys`.
[[nodiscard]] const std::vector<ParamDecl>& surfaceKeyDecls(SurfaceKind kind);

}  // namespace rollspin::scene
