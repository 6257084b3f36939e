// The twin view: the Bloch sphere with the Bloch vector of the marker
// X(s) = Q(s) X(0) and the field direction B/|B| as arrows, their trails,
// and (phase-split facts) the cone B̂ sweeps, whose solid angle is Berry's
// phase; axis and state labels, heading and legend.
#pragma once

#include <memory>
#include <vector>

#include "draw/camera_framing.hpp"
#include "draw/figure_text.hpp"
#include "model/rolling_model.hpp"
#include "motion/frame_sampling.hpp"
#include "motion/scene_facts.hpp"
#include "render/draw_list.hpp"
#include "scene/scene_spec.hpp"

namespace rollspin::draw {

class TwinView {
 public:
  TwinView(const scene::SceneSpec& spec, const model::RollingModel& model,
           const std::shared_ptr<const motion::SceneFacts>& facts, const geometry::Vec3& markerBody,
           std::shared_ptr<render::MeshData> dotMesh, FigureText figureText);

  // Seen from the orbit angles and field of view of `aim`.
  void add(render::DrawList& list, const motion::FrameOrientations& frame, int view,
           const CameraFraming::Aim& aim) const;
  // {heading, legend}: empty for an inset or with labels off.
  // maxWidth: the widest line the view holds (a narrower one names the spin without its formula).
  [[nodiscard]] std::vector<TextBlock> textBlocks(bool inset, float text, float maxWidth = 1e9f) const;
  // Marks the disc the twin's sphere, arrows, trails and axis labels cover.
  void markImportant(Occupancy& occupancy, const render::View& v) const;
  void setWindow(const NdcWindow& window) { window_ = window; }
  // A figure (or text larger than an image's share): the sphere fills the
  // window the text leaves and its labels lie against what they name.
  [[nodiscard]] bool closeLabels() const;

  static constexpr float kAxisLength = 1.18f;         // the drawn axes run from −this to +this
  static constexpr double kFigureSceneRadius = 1.15;  // framed into a figure's window: the axes' ends at its edge

 private:
  void aimAtSphere(render::View& v, const CameraFraming::Aim& aim) const;
  void addSphereAndAxes(render::DrawList& list, int view) const;
  // The field's direction B̂(s) (zero where B vanishes).
  [[nodiscard]] geometry::Vec3 fieldDirection(double s) const;
  void addTrails(render::DrawList& list, const motion::FrameOrientations& frame, int view) const;
  void addArrows(render::DrawList& list, const motion::FrameOrientations& frame, int view) const;
  void addLabels(render::DrawList& list, const render::View& v, int view) const;
  const scene::SceneSpec& spec_;
  FigureText figureText_;
  const model::RollingModel& model_;
  geometry::Vec3 markerBody_;
  NdcWindow window_;
  std::size_t trailGridCount_ = 0;  // the trail grid's points (frame_sampling.hpp)
  std::shared_ptr<render::MeshData> dotMesh_, blochSphereMesh_, fieldConeMesh_;
};

}  // namespace rollspin::draw
