#include "draw/scene_drawer.hpp"

#include <algorithm>
#include <cmath>

#include "draw/text_blocks.hpp"
#include "render/mesh_builders.hpp"

namespace rollspin::draw {

using geometry::Vec3;

SceneDrawer::SceneDrawer(const scene::SceneSpec& spec, const RollingModel& model,
                         std::shared_ptr<const render::TextureImage> ballTexture,
                         std::shared_ptr<const SceneFacts> facts)
    : spec_(spec) {
  const geometry::DarbouxSample start = model.path->at(0.0);
  markerBody_ = spec.ball.marker ? Vec3((*spec.ball.marker)[0], (*spec.ball.marker)[1], (*spec.ball.marker)[2])
                                 : start.normal;
  markerBody_.normalize();
  titleBand_ = !spec.render.title.empty();
  for (const scene::SegmentSpec& seg : spec.segments)
    if (seg.title && !seg.title->empty()) titleBand_ = true;

  auto dotMesh = render::uvSphere(24, 12);  // small dots need few triangles
  if (spec.render.layout != scene::RenderLayout::Ball)
    twin_ = std::make_unique<TwinView>(spec, model, facts, markerBody_, dotMesh);
  ball_ = std::make_unique<BallView>(spec, model, std::move(ballTexture), std::move(facts), markerBody_, dotMesh);
  camera_ = std::make_unique<CameraFraming>(spec, model, ball_->extent());
}

render::DrawList SceneDrawer::draw(const FrameOrientations& frame) const {
  render::DrawList list;
  const auto& rs = spec_.render;
  list.width = static_cast<int>(rs.width);
  list.height = static_cast<int>(rs.height);
  list.msaaSamples = static_cast<int>(rs.msaa);
  list.transparent = rs.transparent;

  int top = 0;
  // A segment's title replaces render.title while it plays; the band stays
  // for the whole clip when any title is set, so the views never jump.
  const scene::SegmentSpec* segment =
      spec_.segments.empty() ? nullptr : &spec_.segments[std::min(frame.story.segment, spec_.segments.size() - 1)];
  if (titleBand_) top = addTitleBand(list, segment && segment->title ? *segment->title : rs.title);
  addViews(list, frame, top);
  return list;
}

void SceneDrawer::addViews(render::DrawList& list, const FrameOrientations& frame, int top) const {
  const int W = list.width, H = list.height;
  const int bodyHeight = H - top;
  const std::string noCaption;
  const std::string& caption =
      spec_.segments.empty() ? noCaption
                             : spec_.segments[std::min(frame.story.segment, spec_.segments.size() - 1)].caption;
  const double s = frame.current.s;
  auto addBall = [&](int x, int w) {
    list.views.push_back(camera_->ballCamera(x, top, w, bodyHeight, s, frame.story));
    ball_->add(list, frame, int(list.views.size()) - 1);
    addCaption(list, caption, int(list.views.size()) - 1);
  };
  // The twin looks along the ball camera's direction (its aim for the twin's
  // own rectangle), so the marker and the Bloch arrow point the same way.
  auto addTwin = [&](render::View twin) {
    list.views.push_back(twin);
    twin_->add(list, frame, int(list.views.size()) - 1, camera_->aimAt(frame.story, twin.width, twin.height, s));
  };
  switch (spec_.render.layout) {
    case scene::RenderLayout::SideBySide: {
      const int ballWidth = static_cast<int>(std::lround(W * 0.6));
      addBall(0, ballWidth);
      render::View twin;
      twin.x = ballWidth;
      twin.y = top;
      twin.width = W - ballWidth;
      twin.height = bodyHeight;
      addTwin(twin);
      break;
    }
    case scene::RenderLayout::Inset: {
      addBall(0, W);
      const int margin = static_cast<int>(std::lround(H * 0.025));
      const int side = static_cast<int>(std::lround(std::min(W, bodyHeight) * 0.42));
      render::View twin;
      twin.x = W - side - margin;
      twin.y = top + margin;
      twin.width = side;
      twin.height = side;
      twin.frame = true;
      addTwin(twin);
      break;
    }
    case scene::RenderLayout::Ball: addBall(0, W); break;
    case scene::RenderLayout::Twin: {
      render::View twin;
      twin.y = top;
      twin.width = W;
      twin.height = bodyHeight;
      addTwin(twin);
      addCaption(list, caption, int(list.views.size()) - 1);
      break;
    }
  }
}

}  // namespace rollspin::draw
