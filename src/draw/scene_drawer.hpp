// SceneDrawer — turns (scene, model, orientation samples) into a DrawList by
// composing the views the layout asks for (title band, ball view, twin view,
// caption) over the camera framing. The ball view shows the textured ball
// at its centre C(s) oriented by worldFromBody = R(U(s)), the surface, the
// contact path (travelled part highlighted), Brockett's glass plate; the
// Bloch-sphere twin shows the Bloch vector of the marker
// X(s) = Q(s) X(0), the field direction B/|B| and their trails. Only what
// the layout shows is built. It never runs the solver: the caller passes the
// orientations (FrameOrientations) it computed.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "draw/ball_view.hpp"
#include "draw/camera_framing.hpp"
#include "draw/clip_layout.hpp"
#include "draw/figure_text.hpp"
#include "draw/twin_view.hpp"
#include "model/rolling_model.hpp"
#include "motion/frame_sampling.hpp"
#include "motion/scene_facts.hpp"
#include "motion/surface_stretches.hpp"
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
  static constexpr double kCameraMove = CameraFraming::kCameraMove;

  // `ballTexture` null: the built-in tennis ball. Meshes are built once here
  // and shared by every frame. `facts` (makeSceneFacts): the scene's fact
  // labels, the tennis ball's marks and the twin's cone of B; null for none.
  // A storyboard of several surfaces draws each surface's stretch
  // (motion/surface_stretches.hpp) with a drawer of its own: its camera, its
  // surface and path; the Bloch sphere's trail runs on through the clip.
  // `figureStillAt`: a figure drawn at this arc length only, framed and laid
  // out for that still (the ball where it is, not its sweep over the clip);
  // ignored unless the text is laid out for a printed size (figure()), a
  // strobe shows one ball, and the scene has one surface. `figureText`: a
  // clip's text, or a printed figure's with its least size
  // (jobs::fitTextToFigure).
  SceneDrawer(const scene::SceneSpec& spec, const RollingModel& model,
              std::shared_ptr<const render::TextureImage> ballTexture,
              std::shared_ptr<const SceneFacts> facts = nullptr, std::optional<double> figureStillAt = std::nullopt,
              FigureText figureText = {});
  ~SceneDrawer();

  [[nodiscard]] render::DrawList draw(const FrameOrientations& frame) const;

  // A cross-fade into a new surface's view (segment.transition = "fade"):
  // the outgoing picture, the previous surface's view with the ball as it
  // left it (FrameOrientations::cuts), and its weight in (0, 1], falling
  // linearly from 1 at the segment's first frame to 0 at
  // segment.fade_seconds; nullopt when the frame is in none.
  struct Fade {
    render::DrawList from;
    double weight = 0.0;
  };
  [[nodiscard]] std::optional<Fade> fadeAt(const FrameOrientations& frame) const;

  // Whether the frame's camera is still on its way from the previous
  // segment's (a held frame must be drawn again).
  [[nodiscard]] bool cameraMoving(const StoryPlace& story) const;

  // The ball view's camera at a place of the clip, as draw() sets it (no
  // solve needed); a default View where the layout shows no ball view.
  [[nodiscard]] render::View ballCamera(const StoryPlace& story, double s) const;

  // Where the scene's own camera keys hide the ball: one warning line per
  // segment, with the seconds (CameraFraming::hiddenWarnings).
  [[nodiscard]] std::vector<std::string> cameraWarnings() const;

  // The marker's body direction X(0) (unit).
  [[nodiscard]] const geometry::Vec3& markerBody() const { return markerBody_; }

 private:
  // One surface's stretch: its scene and model for the ball view and the
  // camera, the whole clip's model (`whole`) for the twin, the marker body
  // direction of the whole clip; `stillAt`: the figure's still lies in
  // this stretch, at this arc length of its own.
  SceneDrawer(const motion::SurfaceStretch& stretch, const RollingModel& whole,
              std::shared_ptr<const render::TextureImage> ballTexture, std::shared_ptr<const SceneFacts> facts,
              const geometry::Vec3& markerBody, FigureText figureText, std::optional<double> stillAt);
  void build(const RollingModel& ball, const RollingModel& whole,
             std::shared_ptr<const render::TextureImage> ballTexture, std::shared_ptr<const SceneFacts> facts);
  // The stretch that shows segment k, and a frame in its own arc length
  // and segment numbers (its trail and strobe cut to the stretch).
  [[nodiscard]] std::size_t stretchOf(std::size_t segment) const;
  [[nodiscard]] FrameOrientations inStretch(const FrameOrientations& frame, std::size_t stretch) const;
  void addViews(render::DrawList& list, const FrameOrientations& frame, const FrameOrientations& whole) const;

  struct Rect {
    int x = 0, y = 0, width = 0, height = 0;
  };
  struct Rects {
    Rect ball, twin;  // width 0: not shown
    bool inset = false;
  };
  [[nodiscard]] Rects rects() const;
  [[nodiscard]] float text() const;       // body text size in pixels
  [[nodiscard]] float leastText() const;  // the least text size in pixels (a figure's 6 pt; 0 in a clip)
  [[nodiscard]] bool figure() const;      // text laid out for a printed size (jobs/figure_job)
  // The title as drawn: a figure leaves out one that needs over a fifth of its height.
  [[nodiscard]] std::string shownTitle(const std::string& title) const;
  [[nodiscard]] const std::string& captionAt(const StoryPlace& story) const;
  [[nodiscard]] std::vector<TextBlock> ballBlocks(const FrameOrientations& frame, float viewWidth) const;
  [[nodiscard]] std::vector<TextBlock> twinBlocks(const FrameOrientations& frame, float viewWidth, bool inset) const;
  void layOut(const RollingModel& model);
  bool layOutBallView(const RollingModel& model, const Rects& r, double minWindow,
                      const std::vector<FrameOrientations>& samples);
  void closeInBesideText(const std::vector<TextBlock>& blocks, const Rects& r,
                         const std::function<Occupancy(const NdcWindow&)>& occupancyFor);
  bool layOutTwinView(const Rects& r, double minWindow, const std::vector<FrameOrientations>& samples);
  render::DrawList drawList(const FrameOrientations& frame, const FrameOrientations& whole) const;
  // Whether a caption would break narrower than kLeastCaptionEm, or find
  // no room, in its view (the ball view's blocks as laid out).
  [[nodiscard]] bool captionCramped(const ViewLayout& layout, const std::vector<TextBlock>& blocks,
                                    float viewWidth) const;
  // If so in a figure: the captions go below the views (captionBandLines_);
  // true when the views must be laid out again.
  bool moveCaptionsBelow(const ViewLayout& layout, const std::vector<TextBlock>& blocks, float viewWidth);

  const scene::SceneSpec& spec_;
  FigureText figureText_;
  std::vector<motion::SurfaceStretch> stretches_;    // empty: one surface, drawn here
  std::vector<std::unique_ptr<SceneDrawer>> parts_;  // one per stretch
  double stretchStart_ = 0.0;                        // a stretch's drawer: where it lies on the whole path
  std::optional<double> stillAt_;                    // a figure framed for its still at this s (figureStillAt)
  geometry::Vec3 markerBody_;
  bool titleBand_ = false;            // render.title or any segment's title: the band is kept for the whole clip
  std::size_t titleLines_ = 1;        // the lines the longest title takes (text_blocks: titleLines)
  std::size_t captionBandLines_ = 0;  // a figure's captions below the views: the most lines one takes (0: in a view)
  std::unique_ptr<TwinView> twin_;    // null when the layout shows no twin
  std::unique_ptr<BallView> ball_;    // with layout = "twin", only its path samples (for the framing)
  std::unique_ptr<CameraFraming> camera_;
  ViewLayout ballLayout_, twinLayout_;                  // decided per clip (layOut)
  std::vector<glm::vec2> ballReserved_, twinReserved_;  // each block's size over the clip
};

}  // namespace rollspin::draw
