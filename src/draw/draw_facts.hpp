// Fact labels for SceneDrawer: SceneFacts (numbers, motion/scene_facts) turned
// into the text lines the ball view prints at arc length s — each measured
// value beside its closed form — and the twin's cone of B̂ as a mesh.
// Formatting only: every number comes from SceneFacts or the frame's U(s).
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "motion/frame_sampling.hpp"
#include "motion/scene_facts.hpp"
#include "render/draw_list.hpp"

namespace rollspin::draw {

using model::RollingModel;
using motion::FrameOrientations;
using motion::OrientedSample;
using motion::SceneFacts;
using motion::StoryPlace;

// One line of facts; `live` when it shows a running value (its text changes
// from frame to frame, so a retained layer must not keep it). Lines that
// change only at a mark or at the end count as fixed: a layer is rebuilt then.
struct FactLine {
  std::string text;
  bool live = false;
  FactLine(std::string t, bool isLive = false) : text(std::move(t)), live(isLive) {}  // NOLINT: implicit from text
  FactLine(const char* t) : text(t) {}                                                // NOLINT
};

// The lines for the facts the scene shows, at the frame's s (live values
// use frame.current.q). A strobe shows the circuit's values only; a still
// (frame.still) shows them beside the values at s, where a clip shows "…"
// until its last frame.
[[nodiscard]] std::vector<FactLine> factLines(const SceneFacts& facts, const FrameOrientations& frame,
                                              double pathLength);

// A fan of triangles from the origin through the closed loop of B̂ (unit
// vectors): the cone whose solid angle is Berry's phase.
[[nodiscard]] std::shared_ptr<render::MeshData> coneMesh(const std::vector<geometry::Vec3>& loop);

}  // namespace rollspin::draw
