// Camera framing for the ball view: orbit angles (azimuth, elevation) from
// the scene, the target and distance that keep everything that moves in
// view (fitPoints), one shot per storyboard segment, and the eased move
// (3x² − 2x³) from one shot to the next; plus the key light that goes with
// a camera. Plain geometry: no GL.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "draw/clip_layout.hpp"
#include "draw/sight_lines.hpp"
#include "geometry/surface.hpp"
#include "model/rolling_model.hpp"
#include "motion/frame_sampling.hpp"
#include "render/draw_list.hpp"
#include "scene/scene_spec.hpp"

namespace rollspin::draw {

struct OrbitAngles {
  double azimuth = 0.0, elevation = 0.0;  // radians
};

// The unit vector from the target towards the eye.
geometry::Vec3 towardEye(const OrbitAngles &a);
// The angle between two view directions, in degrees.
double turnDeg(const OrbitAngles &a, const OrbitAngles &b);

// render.azimuth_deg / elevation_deg, with the defaults a surface asks for
// where the scene leaves them out (a wall from its side, a ceiling from
// below, a strobe from high up).
OrbitAngles orbitAngles(const scene::SceneSpec &spec, const model::RollingModel &model);

// A key light from the upper left, slightly in front of the subject; its
// shadow map covers the sphere (centre, radius).
render::Light keyLight(const glm::vec3 &up, const glm::vec3 &eyeDirection, const glm::vec3 &centre, float radius);

// A view of the rectangle (x, y, w, h) looking at `target` from `distance`
// along the orbit angles, z up; near/far planes enclose sceneRadius.
render::View orbitView(int x, int y, int w, int h, const glm::vec3 &target, double distance, const OrbitAngles &a,
                       double fovDeg, double sceneRadius);

// The narrower lens that frames a subject into `window` of a view seen with
// (fovDeg, aspect), and the off-axis projection that puts that lens's axis
// at the window's centre.
struct Lens {
  double fovDeg, aspect;
};
Lens windowLens(const NdcWindow &window, double fovDeg, double aspect);
bool isWholeView(const NdcWindow &window);
glm::mat4 offAxisProjection(const NdcWindow &window, double fovDeg, double aspect, float nearPlane, float farPlane);

// Distance at which a sphere of radius r fills the smaller field of view.
double fitDistance(double radius, double fovDeg, double aspect);

// Target and distance that keep every point (padded by `pad`, or by
// pads[i] where `pads` is given) inside the field of view, seen from the
// orbit direction.
std::pair<geometry::Vec3, double> fitPoints(const std::vector<geometry::Vec3> &points, double pad, const OrbitAngles &a,
                                            double fovDeg, double aspect, const std::vector<double> &pads = {});

// What the default camera keeps in view: sample points (each padded by the
// ball's radius when framed) and the bounding sphere of all that moves; and
// the drawn surface, which can hide the ball (none for a plane).
struct FrameExtent {
  std::vector<geometry::Vec3> points;
  std::vector<double> pads;  // per point; empty: each padded by the ball's radius
  [[nodiscard]] double padOf(std::size_t i, double ballRadius) const { return pads.empty() ? ballRadius : pads[i]; }
  geometry::Vec3 centre = geometry::Vec3::Zero();  // shadow-map centre
  double radius = 1.0;
  std::shared_ptr<const SightLines> surface;
  // The drawn surface's outline on the path's side (an outside sphere: its
  // half under the path): a view's edge inside the frame (the seam to the
  // twin view, the title band) must not cut it where panning the subject
  // away from that edge, within the room the window leaves, holds it.
  std::vector<geometry::Vec3> outline;
};

class CameraFraming {
 public:
  // A camera change between segments moves smoothly (3x² − 2x³) over this
  // many seconds (or the whole segment, when it is shorter).
  static constexpr double kCameraMove = 1.0;

  struct Aim {
    geometry::Vec3 target;
    double distance, azimuth, elevation, fovDeg;
  };

  // Cameras: [render]'s (with the defaults orbitAngles derives), then each
  // segment's keys laid over the previous segment's camera.
  // `forStill`: the extent is one still's (BallView::stillExtent), already
  // framed for its own place: no segment closes in (kLeastBallShare).
  CameraFraming(const scene::SceneSpec &spec, const model::RollingModel &model, FrameExtent extent,
                bool forStill = false);

  // The camera of a frame: its segment's, or on the way there from the
  // previous segment's during the first kCameraMove seconds.
  [[nodiscard]] Aim aimAt(const motion::StoryPlace &story, int w, int h, double s) const;
  // The ball view's camera and key light for the rectangle (x, y, w, h).
  [[nodiscard]] render::View ballCamera(int x, int y, int w, int h, double s, const motion::StoryPlace &story) const;

  // Frame the subject into this part of the ball view (the rest is left to
  // text); the full view by default. Explicit distance/target keys ignore it.
  void setWindow(const NdcWindow &window) { window_ = window; }
  // Which edges of the ball view lie inside the frame (next to another view
  // or the title band), where the surface's outline must not be cut.
  struct InnerEdges {
    bool left = false, right = false, bottom = false, top = false;
  };
  void setInnerEdges(const InnerEdges &edges) { innerEdges_ = edges; }
  // Whether a storyboard's segments may frame their own stretches where
  // the whole clip's framing leaves the ball small (kLeastBallShare), and
  // how far of the way they go: 0 frames the whole clip in every segment,
  // 1 as close as the ball asks (where the text leaves less room, between).
  [[nodiscard]] bool mayCloseIn() const;  // some segment may (whatever share setCloseInShare gives)
  void setCloseInShare(double share) { closeIn_ = share; }
  // Whether the scene fixes the camera itself (target and distance, or
  // follow), so that the framing cannot make room for text.
  [[nodiscard]] bool fixedByScene() const;
  // Whether the default camera orbits with the ball (its view changes with s).
  [[nodiscard]] bool orbits() const;
  // Whether the camera is on its way from the previous segment's (the
  // first moveSeconds of a segment whose camera differs).
  [[nodiscard]] bool moving(const motion::StoryPlace &story) const;
  // Whether the camera of this place moves with the ball (follow).
  [[nodiscard]] bool follows(const motion::StoryPlace &story) const;
  // Whether the surface is cut away towards the eye at this place where it
  // hides the ball (BallView): where the scene leaves the view free and no
  // view rollspin tried keeps the ball in sight past the surface (once round
  // a torus's tube), also while the camera moves into or out of that segment.
  [[nodiscard]] bool cutsAway(const motion::StoryPlace &story) const;

  // Where the scene's own camera keys force a view that hides the ball
  // (< 90 % of its disc seen past the surface): one line per segment, naming
  // it and the seconds of the clip (empty when none does).
  [[nodiscard]] std::vector<std::string> hiddenWarnings() const;

  // Where the scene leaves the camera free, a move between segments turns
  // the view direction by at most this many degrees a second (the moves
  // storyboard.toml asks for turn it by up to about 36° in their second):
  // a larger turn takes longer than kCameraMove.
  static constexpr double kMaxFreeMoveDeg = 40.0;
  // The fastest the view direction turns where the scene leaves the camera
  // free: the peak of a kMaxFreeMoveDeg move eased over a second
  // (3x² − 2x³ peaks at 1.5 times its mean rate). A camera that orbits with
  // the ball or turns with s (round a torus's tube) keeps under it too.
  static constexpr double kMaxTurnRateDeg = 1.5 * kMaxFreeMoveDeg;

 private:
  // A view direction the camera passes through at arc length s.
  struct Keyframe {
    double s = 0.0;
    OrbitAngles angles;
  };
  struct Shot {
    double azimuth = 0.0, elevation = 0.0,
           fovDeg = 32.0;  // radians, radians, degrees
    std::optional<geometry::Vec3> target{};
    std::optional<double> distance{};
    bool follow = false;
    bool orbits = false;               // the azimuth follows the ball's longitude (a path
                                       // round the z axis)
    double orbitOffset = 0.0;          // ... plus this
    double moveSeconds = kCameraMove;  // the move here from the previous segment's camera
    bool keyed = false;                // the scene's keys fix (part of) this camera
    bool cutsAway = false;             // the surface is cut away where it hides the ball
    std::vector<Keyframe> keys{};      // non-empty: the view direction turns with s
                                       // through these (unhiddenAngles)
    // A storyboard's free camera: the stretch of path it is framed for
    // (a hold: the next motion's), closer than the whole clip's framing
    // where that leaves the ball under kLeastBallShare (ownStretch).
    bool ownStretch = false;
    double stretchStart = 0.0, stretchEnd = 0.0;
  };
  [[nodiscard]] static Shot sceneShot(const scene::SceneSpec &spec, const OrbitAngles &angles);
  // A storyboard's ball takes at least this share of its view's height
  // (docs/rendering.md) unless its segment's own path spans more: the
  // camera of that segment comes closer, towards the fit of its own stretch.
  static constexpr double kLeastBallShare = 0.105;
  // The target and distance of `shot`, framed for the whole clip, brought
  // closer where the ball would be under kLeastBallShare (ownStretch).
  static void layCameraKeys(const scene::CameraSpec &c, Shot &shot);
  // Steps a camera moving between two shots back where the ball at s would
  // come closer than kEdgeMargin to the window's edge.
  void keepBallInView(Aim &mixed, const Aim &from, const Aim &to, double x, int w, int h, double s) const;
  // Gives back-to-back turning cameras a move where either frames its own
  // stretch, and widens each ownStretch shot's stretch over the next motion's camera move.
  void holdTheMovesAhead(const std::vector<double> &segmentSeconds);
  void closeInOnStretch(const Shot &shot, const OrbitAngles &a, double fovDeg, double aspect, geometry::Vec3 &target,
                        double &distance) const;
  // A view chosen to keep the ball in sight over [s0, s1].
  struct Unhidden {
    OrbitAngles angles;
    bool orbits = false;
    double orbitOffset = 0.0;
    double share = 1.0;            // the least share of the ball seen (sight lines)
    bool cutAway = false;          // none sees it: cut the surface away towards the eye
    std::vector<Keyframe> keys{};  // see Shot
  };
  // The view direction at s through keyframes (mixed between neighbours).
  [[nodiscard]] static OrbitAngles along(const std::vector<Keyframe> &keys, double s);
  [[nodiscard]] Aim aimOf(const Shot &shot, int w, int h, double s) const;
  // fitPoints, then (held: a free camera) holdOutline and keepOffViewEdges,
  // for the orbit angles and lens: what aimOf frames the subject with. The
  // same inputs give the same bits, so each distinct set is computed once
  // (a layout samples the clip with up to 480 cameras of one shot).
  [[nodiscard]] std::pair<geometry::Vec3, double> framedFit(const OrbitAngles &a, double fovDeg, double aspect,
                                                            bool held) const;
  // What framedFit depends on besides the subject, bit for bit: the angles,
  // the lens, the window, the inner edges and `held`.
  using FitKey = std::array<std::uint64_t, 9>;
  // Bounded: a camera that turns with s adds an entry a frame.
  static constexpr std::size_t kMaxFits = 4096;
  // Moves `target` across the view so that the outline stays inside the
  // inner edges, as far as the subject's points stay inside the window,
  // then steps back by up to kOutlineStepBack where it is still cut.
  void holdOutline(geometry::Vec3 &target, double &distance, const OrbitAngles &a, double fovDeg, double aspect) const;
  // How far back holdOutline may step (a slightly wider framing).
  static constexpr double kOutlineStepBack = 1.2;
  // Steps back where the subject's points (padded by R) come closer than
  // kEdgeMargin to an edge of the view that the window reaches (a window
  // narrowed for text leaves fitPoints' margin, a share of the window,
  // smaller there), so that the frame does not touch the ball.
  void keepOffViewEdges(const geometry::Vec3 &target, double &distance, const OrbitAngles &a, double fovDeg,
                        double aspect) const;
  // The least room between the subject and the view's edge, in the view's
  // NDC (3 % of its width or height).
  static constexpr double kEdgeMargin = 0.06;
  // The orbit angles `base`, turned where the surface would hide the ball on
  // [s0, s1] (azimuthFree/elevationFree: which the scene leaves open); with
  // mayOrbit, a view that orbits with the ball's longitude where no still
  // view sees it, else one that turns with s; maxTurnDeg bounds the turn
  // away from `base`; the motion over [s0, s1] lasts `seconds`.
  [[nodiscard]] Unhidden unhiddenAngles(OrbitAngles base, double s0, double s1, bool azimuthFree, bool elevationFree,
                                        bool mayOrbit, double maxTurnDeg, double seconds, bool mayLower = false,
                                        bool follow = false) const;
  void findHiddenSpans();

  const scene::SceneSpec &spec_;
  const model::RollingModel &model_;
  FrameExtent extent_;
  NdcWindow window_;
  InnerEdges innerEdges_;
  double closeIn_ = 1.0;
  std::vector<Shot> shots_;  // one per storyboard segment (one for a scene without segments)
  std::vector<std::string> hiddenWarnings_;
  mutable std::mutex fitsMutex_;
  mutable std::map<FitKey, std::pair<geometry::Vec3, double>> fits_;
};

}  // namespace rollspin::draw
