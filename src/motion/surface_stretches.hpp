// SurfaceStretch — a storyboard of several surfaces seen one surface at a
// time: a run of segments on one surface (its motions and the holds after
// them) as a storyboard of its own, its path from s = 0. Drawing frames
// each surface's stretch by itself (its camera, its surface mesh), while the
// solver runs once over the whole path so the ball's orientation carries
// across: a frame at s of the whole clip is shown by the stretch holding s
// at s − start, its segment k at k − firstSegment.
#pragma once

#include <cstddef>
#include <vector>

#include "model/rolling_model.hpp"
#include "scene/scene_spec.hpp"

namespace rollspin::motion {

struct SurfaceStretch {
  std::size_t firstSegment = 0, endSegment = 0;  // [first, end) of the scene's segments
  double start = 0.0, end = 0.0;                 // where it lies on the whole path
  scene::SceneSpec spec;      // its segments (each motion's duration fixed as the whole clip times it), its surface
  model::RollingModel model;  // built from `spec`: the same pieces, from s = 0
};

// One stretch per surface change, in order (a motion that gives its own
// surface starts one; holds before the first motion stay with it). Empty
// for a scene of one surface: nothing to split.
[[nodiscard]] std::vector<SurfaceStretch> surfaceStretches(const scene::SceneSpec& spec,
                                                           const model::RollingModel& model);

}  // namespace rollspin::motion
