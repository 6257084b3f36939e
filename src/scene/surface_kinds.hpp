// Surface kinds: the one table of what a scene's [surface] can be — each
// kind's name, the kind-specific keys it accepts, its flags (of revolution,
// a height field) and the path it gets when [path] names no kind. The loader,
// the printer and the messages read this table; model/surface_kinds.cpp
// holds the matching geometry factories. A new kind touches three files: its
// geometry class, a row here (surface_kinds.cpp) and a factory row there.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

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

struct SurfaceKindRow {
  SurfaceKind kind;
  std::string_view name;  // kind.name()
  std::vector<std::string> keys;  // its own keys of [surface] (besides kind)
  bool ofRevolution;              // parallels lie on it (a paraboloid only when a = b)
  bool heightField;               // side is "above" | "below" (else "outside" | "inside")
  PathKind defaultPath;           // [path] without a kind
};

[[nodiscard]] std::span<const SurfaceKindRow> surfaceKinds();
[[nodiscard]] const SurfaceKindRow& surfaceKindRow(SurfaceKind kind);
// Every kind-specific key of any kind, in the table's order (no duplicates).
[[nodiscard]] const std::vector<std::string>& allSurfaceKeys();

}  // namespace rollspin::scene
