// The ball view: the textured ball at its centre C(s) oriented by
// worldFromBody = R(U(s)) (or a strobe of them), the surface it rolls on,
// the contact path (travelled part highlighted), the marker's trail,
// Brockett's glass plate and the tennis ball's marks, with the view's
// heading and running values. Meshes are built once and shared by frames.
#pragma once

#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "draw/camera_framing.hpp"
#include "draw/figure_text.hpp"
#include "model/rolling_model.hpp"
#include "motion/frame_sampling.hpp"
#include "motion/scene_facts.hpp"
#include "render/draw_list.hpp"
#include "scene/scene_spec.hpp"

namespace rollspin::draw {

class BallView {
 public:
  // `ballTexture` null: the built-in tennis ball. With layout = "twin" only
  // the path is sampled (the camera framing still reads it).
  BallView(const scene::SceneSpec& spec, const model::RollingModel& model,
           std::shared_ptr<const render::TextureImage> ballTexture, std::shared_ptr<const motion::SceneFacts> facts,
           const geometry::Vec3& markerBody, std::shared_ptr<render::MeshData> dotMesh, FigureText figureText);

  // What the default camera must keep in view.
  [[nodiscard]] const FrameExtent& extent() const { return extent_; }
  // What a figure's camera must keep in view, the still at arc length s:
  // extent() with the ball's centres over the clip replaced by the drawn
  // path and the ball's sweep up to s (a still shows the ball and its
  // marker's trail so far, not the rest of its sweep).
  [[nodiscard]] FrameExtent stillExtent(double s) const;

  // The meshes the view draws, for an export (glTF) that shows the same:
  // the surface (null where the layout or the scene shows none) with its
  // material, the unit ball sphere and the ball's texture (the tennis ball
  // unless the scene gives one).
  [[nodiscard]] std::shared_ptr<const render::MeshData> surfaceMesh() const { return surfaceMesh_; }
  [[nodiscard]] const render::Material& surfaceMaterial() const { return surfaceMaterial_; }
  [[nodiscard]] std::shared_ptr<const render::MeshData> ballMesh() const { return sphereMesh_; }
  [[nodiscard]] std::shared_ptr<const render::TextureImage> ballTexture() const { return ballTexture_; }

  // `cutAwayFrom`: the eye of a view that cannot see the ball past the
  // surface (CameraFraming::cutsAway): where the surface hides the ball
  // from there, its part nearer the eye is cut away, with a rim line.
  void add(render::DrawList& list, const motion::FrameOrientations& frame, int view,
           const std::optional<geometry::Vec3>& cutAwayFrom = std::nullopt) const;
  // The view's text for this frame: {heading and facts, running values}
  // (empty blocks when labels are off); `text` is the body size in pixels.
  [[nodiscard]] std::vector<TextBlock> textBlocks(const motion::FrameOrientations& frame, float text) const;
  // A surface's stretch of a longer storyboard (motion/surface_stretches):
  // the running s is shown as the whole clip's, start + s of `wholeLength`.
  void showWholeArcLength(double start, double wholeLength) {
    shownStart_ = start;
    shownLength_ = wholeLength;
  }
  // Marks what the view shows at s that text must not cover: the ball and
  // (withPath) the contact path; the plate's trail so far.
  void markImportant(Occupancy& occupancy, const render::View& v, double s, bool withPath) const;
  // The screen bounds (the view's pixels, y down, clipped to it) of the
  // surface as drawn and the ball at s: the subject a figure keeps at half
  // its view (docs/figures.md).
  [[nodiscard]] std::pair<glm::vec2, glm::vec2> subjectBounds(const render::View& v, double s) const;
  // Whether the surface is drawn as a board (a plane): a patch cut to the
  // path, not a subject of its own.
  [[nodiscard]] bool surfaceIsBoard() const { return surfaceIsBoard_; }

 private:
  void addSurface(render::DrawList& list, double s, int view, const std::optional<geometry::Vec3>& cutAwayFrom) const;
  void addPath(render::DrawList& list, double s, int view) const;
  void addBall(render::DrawList& list, const motion::OrientedSample& pose, int view) const;
  void addMarkerTrail(render::DrawList& list, const motion::FrameOrientations& frame, int view) const;
  void addPlate(render::DrawList& list, double s, int view) const;
  void addMarks(render::DrawList& list, double s, bool plateShown, int view) const;
  // Brockett's plate: its disc mesh, the circle its point traces, and what
  // the framing holds of it (points, and the box lo..hi grown by its disc).
  void framePlate(geometry::Vec3& lo, geometry::Vec3& hi);
  // The surface's material for a frame whose eye is `eye` with the ball at
  // `centre`, cut away towards the eye as far as the ball is hidden, and
  // the cut's rim (empty where nothing is cut).
  render::Material cutTowardEye(const geometry::Vec3& eye, const geometry::Vec3& centre,
                                std::vector<std::vector<geometry::Vec3>>& rim) const;
  // Brockett's plate: the point of the plate above the contact point P(s),
  // lifted by `lift` above the ball's top.
  geometry::Vec3 platePoint(double s, double lift) const;
  // The glass disc drawn for the plate at s (centre, radius): the window of
  // the plate that holds its marked point and the ball's top.
  std::pair<geometry::Vec3, double> plateDisc(double s) const;

  const scene::SceneSpec& spec_;
  FigureText figureText_;
  const model::RollingModel& model_;
  geometry::Vec3 markerBody_;
  std::vector<geometry::Vec3> pathPoints_;  // dense samples of P(s)
  std::vector<double> pathS_;
  std::size_t trailGridCount_ = 0;  // the trail grid's points (frame_sampling.hpp)
  double shownStart_ = 0.0;         // showWholeArcLength
  std::optional<double> shownLength_;
  FrameExtent extent_;
  std::size_t centrePoints_ = 0;            // extent_.points' first: the ball's centres over the clip
  std::vector<std::size_t> surfacePoints_;  // extent_.points on the surface (ascending)
  std::shared_ptr<const render::TextureImage> ballTexture_;
  std::shared_ptr<const motion::SceneFacts> facts_;
  std::shared_ptr<render::MeshData> sphereMesh_, dotMesh_, surfaceMesh_, discMesh_;
  render::Material surfaceMaterial_;
  bool surfaceIsBoard_ = true;  // see surfaceIsBoard()
  geometry::Vec3 plateCircleCentre_ = geometry::Vec3::Zero();
  std::vector<geometry::Vec3> cutRim_;
  std::vector<std::vector<geometry::Vec3>>
      framedEdges_;  // stretches of the surface's edge the framing holds  // inside a sphere: the edge of the cut-away
};

}  // namespace rollspin::draw
