// SceneDrawer — turns (scene, model, orientation samples) into a DrawList:
// the textured ball at its centre C(s) oriented by worldFromBody = R(U(s)),
// the surface, the contact path (travelled part highlighted), Brockett's
// glass plate, and the Bloch-sphere twin with the Bloch vector of the marker
// X(s) = Q(s) X(0), the field direction B/|B| and their trails. Only what
// the layout shows is built. It never runs the solver: the caller passes the
// orientations (FrameOrientations) it computed.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "motion/frame_sampling.hpp"
#include "motion/scene_facts.hpp"
#include "model/rolling_model.hpp"
#include "render/draw_list.hpp"
#include "scene/scene_spec.hpp"
#include "spin/su2.hpp"

namespace rollspin::draw {

using model::RollingModel;
using motion::FrameOrientations;
using motion::OrientedSample;
using motion::SceneFacts;
using motion::StoryPlace;

class SceneDrawer {
 public:
  // A camera change between segments moves smoothly (3x² − 2x³) over this
  // many seconds (or the whole segment, when it is shorter).
  static constexpr double kCameraMove = 1.0;

  // `ballTexture` null: the built-in tennis ball. Meshes are built once here
  // and shared by every frame. `facts` (makeSceneFacts): the scene's fact
  // labels, the tennis ball's marks and the twin's cone of B; null for none.
  SceneDrawer(const scene::SceneSpec& spec, const RollingModel& model,
              std::shared_ptr<const render::TextureImage> ballTexture,
              std::shared_ptr<const SceneFacts> facts = nullptr);

  [[nodiscard]] render::DrawList draw(const FrameOrientations& frame) const;

  // The marker's body direction X(0) (unit).
  [[nodiscard]] const geometry::Vec3& markerBody() const { return markerBody_; }

 private:
  void addBallView(render::DrawList& list, const FrameOrientations& frame, int view) const;
  void addTwinView(render::DrawList& list, const FrameOrientations& frame, int view) const;
  // The camera of a frame: its segment's, or on the way there from the
  // previous segment's during the first kCameraMove seconds.
  struct Shot {
    double azimuth = 0.0, elevation = 0.0, fovDeg = 32.0;  // radians, radians, degrees
    std::optional<geometry::Vec3> target;
    std::optional<double> distance;
    bool follow = false;
  };
  struct Aim {
    geometry::Vec3 target;
    double distance, azimuth, elevation, fovDeg;
  };
  [[nodiscard]] Aim aimOf(const Shot& shot, int w, int h, double s) const;
  [[nodiscard]] Aim aimAt(const StoryPlace& story, int w, int h, double s) const;
  render::View ballCamera(int x, int y, int w, int h, double s, const StoryPlace& story) const;
  void addCaption(render::DrawList& list, const FrameOrientations& frame, int view) const;
  std::vector<Shot> shots_;  // one per storyboard segment (one for a scene without segments)
  bool titleBand_ = false;   // render.title or any segment's title: the band is kept for the whole clip
  render::View ballCamera(int x, int y, int w, int h, double s) const;
  void addMarks(render::DrawList& list, double s, bool plateShown, int view) const;
  void addFactLabels(render::DrawList& list, const FrameOrientations& frame, int view, float top) const;
  // Brockett's plate: the point of the plate above the contact point P(s),
  // lifted by `lift` above the ball's top.
  geometry::Vec3 platePoint(double s, double lift) const;
  // The glass disc drawn for the plate at s (centre, radius): the window of
  // the plate that holds its marked point and the ball's top.
  std::pair<geometry::Vec3, double> plateDisc(double s) const;

  const scene::SceneSpec& spec_;
  const RollingModel& model_;
  geometry::Vec3 markerBody_;
  std::vector<geometry::Vec3> pathPoints_;  // dense samples of P(s)
  std::vector<double> pathS_;
  geometry::Vec3 frameCentre_ = geometry::Vec3::Zero();  // shadow-map centre
  double frameRadius_ = 1.0;                             // bounding radius of all that moves
  std::vector<geometry::Vec3> framePoints_;  // the default camera keeps these (padded by R) in view
  std::shared_ptr<const render::TextureImage> ballTexture_;
  std::shared_ptr<const SceneFacts> facts_;
  std::shared_ptr<render::MeshData> fieldConeMesh_;  // phase-split: the cone of B̂ in the twin
  std::shared_ptr<render::MeshData> sphereMesh_, dotMesh_, surfaceMesh_, blochSphereMesh_, discMesh_;
  render::Material surfaceMaterial_;
  glm::mat4 surfaceFromModel_{1.0f};
  geometry::Vec3 plateCircleCentre_ = geometry::Vec3::Zero();
  std::vector<geometry::Vec3> cutRim_;  // inside a sphere: the edge of the cut-away
};

}  // namespace rollspin::draw
