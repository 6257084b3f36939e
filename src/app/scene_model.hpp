// RollingModel — a validated SceneSpec turned into geometry: the ball radius,
// the surface and the contact path (and Brockett's plate when present).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "geometry/contact_path.hpp"
#include "geometry/surface.hpp"
#include "scene/scene_spec.hpp"

namespace rollspin::app {

struct PlateModel {
  double radius = 0.0;                    // R1, the circle each plate point describes
  double contactSpeedRatio = 2.0;         // |v_plate| / |v_contact| from the rolling constraint
  geometry::Vec3 initialTopPoint = geometry::Vec3::Zero();  // plate touches the ball here at s = 0
};

struct RollingModel {
  double ballRadius = 1.0;
  std::shared_ptr<const geometry::Surface> surface;
  std::unique_ptr<geometry::ContactPath> path;
  std::optional<PlateModel> plate;
};

[[nodiscard]] RollingModel buildModel(const scene::SceneSpec& spec);

// The same two steps as every command runs them, recorded in the StageLog
// ("scene", "model").
[[nodiscard]] scene::SceneSpec loadScene(const std::string& file, const std::vector<std::string>& overrides);
[[nodiscard]] RollingModel buildSceneModel(const scene::SceneSpec& spec);

}  // namespace rollspin::app
