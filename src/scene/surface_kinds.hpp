// Surface kinds: the one table of what a scene's [surface] can be — each
// kind's name, the kind-specific keys it accepts, its flags (of revolution,
// a height field) and the path it gets when [path] names no kind. The loader,
// the printer and the messages read this table; model/surface_kinds.cpp
// holds the matching geometry factories. A new kind: its geometry class, a
// row here, a row there.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace rollspin::scene {

enum class SurfaceKind { Plane, Sphere, Cylinder, Torus, Paraboloid, Saddle, Height };
enum class PathKind;

struct SurfaceKindRow {
  SurfaceKind kind;
  std::string_view name;
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
