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

#include "app/frame_clock.hpp"
#include "app/scene_facts.hpp"
#include "app/scene_model.hpp"
#include "render/draw_list.hpp"
#include "scene/scene_spec.hpp"
#include "spin/su2.hpp"

namespace rollspin::app {

struct OrientedSample {
  double s = 0.0;
  spin::Su2 q;  // U(s): worldFromBody
};

// Everything time-dependent one image needs.
struct FrameOrientations {
  OrientedSample current;              // the ball (and the twin's arrows) at s
  StoryPlace story;                    // a storyboard's segment (caption, title, camera) and its time
  std::vector<OrientedSample> trail;   // U on [0, s], increasing s, for the Bloch trail
  std::vector<OrientedSample> strobe;  // render.strobe > 1: the extra ball positions
};

// The trail's fixed grid g_i = L·i/(count − 1), i = 0 … count − 1 (g_last =
// L exactly): ≥ 240 points over the path, 120 per turn, at most 20001. The
// trail of the frame at s is {g_i < s} ∪ {s} (plus g_0 when s = 0), so every
// frame's trail is a prefix of one sequence: one march serves a whole clip,
// and a trail's vertices stay put from frame to frame instead of sliding.
struct TrailGrid {
  double length = 0.0;
  std::size_t count = 0;  // 0 when render.trails = false
  [[nodiscard]] double at(std::size_t i) const {
    return i + 1 == count ? length : length * double(i) / double(count - 1);
  }
};
[[nodiscard]] TrailGrid trailGrid(const scene::SceneSpec& spec, const RollingModel& model);

// Arc lengths the solver must report for a still at `s`: the trail samples
// (above) and the strobe positions (sorted, inside [0, L]).
struct FrameSampling {
  std::vector<double> trail;
  std::vector<double> strobe;
};
[[nodiscard]] FrameSampling frameSampling(const scene::SceneSpec& spec, const RollingModel& model, double s);
// The strobe positions alone (empty unless render.strobe > 1).
[[nodiscard]] std::vector<double> strobeArcLengths(const scene::SceneSpec& spec, const RollingModel& model);

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

}  // namespace rollspin::app
