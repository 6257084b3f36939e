// RollingModel — a validated SceneSpec turned into geometry: the ball radius,
// the surface and the contact path (and Brockett's plate when present).
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "geometry/contact_path.hpp"
#include "geometry/surface.hpp"
#include "scene/scene_loader.hpp"
#include "scene/scene_spec.hpp"

namespace rollspin::model {

struct PlateModel {
  double radius = 0.0;                                      // R1, the circle each plate point describes
  double contactSpeedRatio = 2.0;                           // |v_plate| / |v_contact| from the rolling constraint
  geometry::Vec3 initialTopPoint = geometry::Vec3::Zero();  // plate touches the ball here at s = 0
};

// Where a storyboard segment lies on the whole path: [start, end] in arc
// length (a hold: start = end, the point where the ball rests), and the
// index in RollingModel::surfaces of the surface it rolls on.
struct SegmentSpan {
  double start = 0.0, end = 0.0;
  std::size_t surface = 0;
};

struct RollingModel {
  double ballRadius = 1.0;
  std::shared_ptr<const geometry::Surface> surface;  // surfaces[0]
  // One per surface of the scene, in order (SceneSpec::surfaceIndexOf): a
  // storyboard whose segments give their own surfaces has several; where
  // the surface changes the path jumps (the JoinedPath's pieces need not
  // meet there) and the ball's orientation carries on.
  std::vector<std::shared_ptr<const geometry::Surface>> surfaces;
  std::unique_ptr<geometry::ContactPath> path;  // a storyboard: a geometry::JoinedPath of its motions
  std::optional<PlateModel> plate;
  std::vector<SegmentSpan> segments;  // one per scene segment; empty unless a storyboard
};

// A storyboard's paths are placed one after another: on a plane a line,
// circle or clothoid after the first starts at the previous end point along
// the previous end heading; any other path is placed by its own keys and
// must start where the previous one ended (within kJoinTolerance · R), else
// BadInput at that segment's path. A geodesic after the first starts by
// default at the previous end point, along the previous end heading. A
// segment that gives its own surface starts afresh: its path is placed by
// its own keys on that surface (its default start), with no join check.
inline constexpr double kJoinTolerance = 1e-6;

[[nodiscard]] RollingModel buildModel(const scene::SceneSpec& spec);

// The same two steps as every command runs them, recorded in the StageLog
// ("scene", "model").
// `settings`: keys command-line flags set (scene_loader.hpp).
[[nodiscard]] scene::SceneSpec loadScene(const std::string& file, const std::vector<std::string>& overrides,
                                         std::span<const scene::KeySetting> settings = {});
[[nodiscard]] RollingModel buildSceneModel(const scene::SceneSpec& spec);

}  // namespace rollspin::model
