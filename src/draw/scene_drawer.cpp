#include "draw/scene_drawer.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "draw/draw_style.hpp"
#include "draw/label_placement.hpp"
#include "draw/text_blocks.hpp"
#include "render/mesh_builders.hpp"

namespace rollspin::draw {

namespace {

// Each text of `meant` that is not among `shown` (and not empty) is left
// out: the DrawList says so, once.
void noteLeftOut(render::DrawList& list, const std::vector<std::string>& meant, const std::vector<std::string>& shown) {
  for (const std::string& text : meant)
    if (!text.empty() && std::find(shown.begin(), shown.end(), text) == shown.end() &&
        std::find(list.leftOut.begin(), list.leftOut.end(), text) == list.leftOut.end())
      list.leftOut.push_back(text);
}

// keepLabelsClear, noting the labels it left out (their text emptied).
void keepLabelsClearNoting(render::DrawList& list, int view, std::size_t first, bool nearestToAnchor) {
  std::vector<std::string> meant;
  for (std::size_t i = first; i < list.labels.size(); ++i) meant.push_back(list.labels[i].text);
  keepLabelsClear(list, view, first, nearestToAnchor);
  std::vector<std::string> shown;
  for (std::size_t i = first; i < list.labels.size(); ++i) shown.push_back(list.labels[i].text);
  noteLeftOut(list, meant, shown);
}

}  // namespace

using geometry::Vec3;

namespace {

const glm::vec4 kCaptionColor{0.55f, 0.12f, 0.02f, 1.0f};

// A figure's twin: the room left round its sphere's window for the axis
// and pole labels, in lines of body text (a line is about 1.4 em).
constexpr double kTwinLabelMargin = 0.9;
// The least share of its view's shorter side a figure's subject (the
// surface as drawn and the ball; on a plane the ball and its path as the
// layout marks them) keeps.
constexpr double kFigureSubjectShare = 0.5;

// A segment's caption: the lecturer's own text, so it shows even with
// render.labels = false; top centre, else bottom centre.
TextBlock captionBlock(const std::string& caption, float text, float leastPx, float viewWidth) {
  TextBlock block;
  block.slots = {Slot::TopCentre, Slot::BottomCentre};
  block.centred = true;
  if (caption.empty()) return block;
  // 1.2 em on one line where it fits, else as small as the body size to
  // stay on one, else the body size broken onto more (ballBlocks).
  const float preferred = text * 1.2f, room = 0.94f * viewWidth - 2.0f * kBlockPad * preferred;
  const float width = textWidthPx(caption, preferred, true);
  const float size = width <= room ? preferred : std::max({text, leastPx, preferred * room / width});
  block.lines.push_back({caption, size, true, kCaptionColor, false});  // changes only between storyboard steps
  return block;
}

}  // namespace

SceneDrawer::SceneDrawer(const scene::SceneSpec& spec, const RollingModel& model,
                         std::shared_ptr<const render::TextureImage> ballTexture,
                         std::shared_ptr<const SceneFacts> facts, std::optional<double> figureStillAt,
                         FigureText figureText)
    : spec_(spec), figureText_(figureText) {
  const geometry::DarbouxSample start = model.path->at(0.0);
  markerBody_ =
      spec.ball.marker ? Vec3((*spec.ball.marker)[0], (*spec.ball.marker)[1], (*spec.ball.marker)[2]) : start.normal;
  markerBody_.normalize();
  stretches_ = motion::surfaceStretches(spec, model);
  if (stretches_.empty()) {
    if (figure() && spec.render.strobe <= 1) stillAt_ = figureStillAt;
    build(model, model, std::move(ballTexture), std::move(facts));
    return;
  }
  // Several surfaces: a drawer per stretch, each with the whole clip's
  // model for its twin and the whole clip's marker; a figure's still is
  // framed by the stretch that shows it, in that stretch's arc length.
  std::optional<std::size_t> stillStretch;
  if (figure() && spec.render.strobe <= 1 && figureStillAt)
    stillStretch =
        stretchOf(motion::storyPlaceAt(model, std::clamp(*figureStillAt, 0.0, model.path->length())).segment);
  for (std::size_t k = 0; k < stretches_.size(); ++k) {
    const motion::SurfaceStretch& stretch = stretches_[k];
    const std::optional<double> stillAt =
        stillStretch == k ? std::optional<double>(*figureStillAt - stretch.start) : std::nullopt;
    parts_.push_back(std::unique_ptr<SceneDrawer>(
        new SceneDrawer(stretch, model, ballTexture, facts, markerBody_, figureText_, stillAt)));
  }
}

SceneDrawer::SceneDrawer(const motion::SurfaceStretch& stretch, const RollingModel& whole,
                         std::shared_ptr<const render::TextureImage> ballTexture,
                         std::shared_ptr<const SceneFacts> facts, const geometry::Vec3& markerBody,
                         FigureText figureText, std::optional<double> stillAt)
    : spec_(stretch.spec), figureText_(figureText), stretchStart_(stretch.start), markerBody_(markerBody) {
  stillAt_ = stillAt;
  build(stretch.model, whole, std::move(ballTexture), std::move(facts));
}

SceneDrawer::~SceneDrawer() = default;

void SceneDrawer::build(const RollingModel& model, const RollingModel& whole,
                        std::shared_ptr<const render::TextureImage> ballTexture,
                        std::shared_ptr<const SceneFacts> facts) {
  const scene::SceneSpec& spec = spec_;
  titleBand_ = !shownTitle(spec.render.title).empty();
  for (const scene::SegmentSpec& seg : spec.segments)
    if (seg.title && !shownTitle(*seg.title).empty()) titleBand_ = true;
  // The band is as tall as the longest title of the clip needs.
  auto countLines = [&](const std::string& title) {
    if (shownTitle(title).empty()) return;
    titleLines_ = std::max(titleLines_, draw::titleLines(title, text(), float(spec.render.width),
                                                         float(spec.render.height), leastText(), figure())
                                            .lines.size());
  };
  countLines(spec.render.title);
  for (const scene::SegmentSpec& seg : spec.segments)
    if (seg.title) countLines(*seg.title);

  auto dotMesh = render::uvSphere(24, 12);  // small dots need few triangles
  if (spec.render.layout != scene::RenderLayout::Ball)
    twin_ = std::make_unique<TwinView>(spec, whole, facts, markerBody_, dotMesh, figureText_);
  ball_ = std::make_unique<BallView>(spec, model, std::move(ballTexture), std::move(facts), markerBody_, dotMesh,
                                     figureText_);
  if (&model != &whole) ball_->showWholeArcLength(stretchStart_, whole.path->length());
  camera_ = std::make_unique<CameraFraming>(spec, model, stillAt_ ? ball_->stillExtent(*stillAt_) : ball_->extent(),
                                            stillAt_.has_value());
  layOut(model);
}

// The views' rectangles, as addViews cuts the image.
SceneDrawer::Rects SceneDrawer::rects() const {
  const int W = int(spec_.render.width), H = int(spec_.render.height);
  const int top = titleBand_ ? titleBandHeight(titleLines_, text(), figure()) : 0;
  const int bottom = captionBandLines_ > 0 ? captionBandHeight(captionBandLines_, std::max(text(), leastText())) : 0;
  const int bodyHeight = H - top - bottom;
  Rects r;
  switch (spec_.render.layout) {
    case scene::RenderLayout::SideBySide: {
      if (W >= bodyHeight) {
        const int ballWidth = static_cast<int>(std::lround(W * 0.6));
        r.ball = {0, top, ballWidth, bodyHeight};
        r.twin = {ballWidth, top, W - ballWidth, bodyHeight};
      } else {  // a portrait image: the twin under the ball, each as wide as the image
        const int ballHeight = static_cast<int>(std::lround(bodyHeight * 0.6));
        r.ball = {0, top, W, ballHeight};
        r.twin = {0, top + ballHeight, W, bodyHeight - ballHeight};
      }
      break;
    }
    case scene::RenderLayout::Inset: {
      r.ball = {0, top, W, bodyHeight};
      const int margin = static_cast<int>(std::lround(H * 0.025));
      const int side = static_cast<int>(std::lround(std::min(W, bodyHeight) * 0.42));
      r.twin = {W - side - margin, top + margin, side, side};
      r.inset = true;
      break;
    }
    case scene::RenderLayout::Ball: r.ball = {0, top, W, bodyHeight}; break;
    case scene::RenderLayout::Twin: r.twin = {0, top, W, bodyHeight}; break;
  }
  return r;
}

// A figure's text never prints under 6 pt (figure_job sets the scale);
// a clip's has no such floor.
float SceneDrawer::leastText() const { return text() * float(figureText_.leastScale); }

bool SceneDrawer::figure() const { return figureText_.figure(); }

// A figure leaves out a title whose band would take over a fifth of its
// height (a narrow column in large text): its caption says it.
// render.burn_captions = false leaves titles and captions to the subtitle
// track: none in the pixels, and no title band.
std::string SceneDrawer::shownTitle(const std::string& title) const {
  if (!spec_.render.burnCaptions) return {};
  if (title.empty() || !figure()) return title;
  const bool fits = titleFitsFigure(title, text(), float(spec_.render.width), float(spec_.render.height), leastText());
  return fits ? title : std::string();
}

float SceneDrawer::text() const {
  return bodyTextPx(int(spec_.render.width), int(spec_.render.height), spec_.render.fontScale);
}

std::vector<TextBlock> SceneDrawer::ballBlocks(const FrameOrientations& frame, float viewWidth) const {
  std::vector<TextBlock> blocks = ball_->textBlocks(frame, text());
  // With a view beside it on the right (the Bloch sphere), the ball view's
  // top right corner is the middle of the frame's top: the view's heading
  // keeps to its own top left corner, where the framing makes room for it.
  // It makes room with a band across the top: a column at the left would
  // push the subject towards the seam, where the view's edge would cut it.
  const Rects r = rects();
  const bool viewOnTheRight = !r.inset && r.ball.x + r.ball.width < int(spec_.render.width) && !blocks.empty();
  if (viewOnTheRight) std::erase(blocks[0].slots, Slot::TopRight);
  blocks.push_back(
      captionBlock(captionBandLines_ > 0 ? std::string() : captionAt(frame.story), text(), leastText(), viewWidth));
  for (TextBlock& b : blocks) {
    wrapToWidth(b, 0.94f * viewWidth, leastText());
    b.bandOnly = compactText(int(spec_.render.width), int(spec_.render.height));  // a column leaves no subject
  }
  if (viewOnTheRight) blocks[0].bandOnly = true;
  return blocks;
}

std::vector<TextBlock> SceneDrawer::twinBlocks(const FrameOrientations& frame, float viewWidth, bool inset) const {
  std::vector<TextBlock> blocks = twin_->textBlocks(inset, text(), 0.94f * viewWidth);
  if (spec_.render.layout == scene::RenderLayout::Twin)
    blocks.push_back(
        captionBlock(captionBandLines_ > 0 ? std::string() : captionAt(frame.story), text(), leastText(), viewWidth));
  for (TextBlock& b : blocks) {
    wrapToWidth(b, 0.94f * viewWidth, leastText());
    b.bandOnly = compactText(int(spec_.render.width), int(spec_.render.height));
  }
  return blocks;
}

const std::string& SceneDrawer::captionAt(const StoryPlace& story) const {
  static const std::string none;
  return spec_.segments.empty() || !spec_.render.burnCaptions
             ? none
             : spec_.segments[std::min(story.segment, spec_.segments.size() - 1)].caption;
}

bool SceneDrawer::captionCramped(const ViewLayout& layout, const std::vector<TextBlock>& blocks,
                                 float viewWidth) const {
  if (blocks.empty() || layout.lines.size() != blocks.size()) return false;
  const TextBlock& caption = blocks.back();  // ballBlocks, twinBlocks: the caption comes last
  if (caption.lines.empty()) return false;
  const float em = caption.lines.front().sizePx;
  const bool narrow = caption.lines.size() > 1 && 0.94f * viewWidth - 2.0f * kBlockPad * em < kLeastCaptionEm * em;
  return narrow || !layout.found.back() || layout.lines.back() < caption.lines.size();
}

// A figure's caption that would break narrower than kLeastCaptionEm, or
// find no room in its view, goes below the views, in a band as tall as the
// longest caption needs there: the views are laid out again above it.
bool SceneDrawer::moveCaptionsBelow(const ViewLayout& layout, const std::vector<TextBlock>& blocks, float viewWidth) {
  if (!figure() || captionBandLines_ > 0 || !captionCramped(layout, blocks, viewWidth)) return false;
  for (const scene::SegmentSpec& segment : spec_.segments)
    if (!segment.caption.empty())
      captionBandLines_ =
          std::max(captionBandLines_,
                   captionBandLines(segment.caption, std::max(text(), leastText()), float(spec_.render.width)).size());
  if (captionBandLines_ == 0) return false;
  ballLayout_ = twinLayout_ = ViewLayout{};
  ballReserved_.clear();
  twinReserved_.clear();
  camera_->setWindow(NdcWindow{});
  return true;
}

namespace {

// The plates of a view's placed blocks (view pixels, y down), each as wide
// as the widest it gets over the clip; as tall as the lines it keeps with
// keptLinesOnly, else as its tallest over the clip. A block the layout found no room for
// (it lies partly off the view) takes none: the still puts it where it is
// clear of the subject, if anywhere (keepBlocksClear).
std::vector<std::pair<glm::vec2, glm::vec2>> placedPlates(const std::vector<TextBlock>& blocks,
                                                          const ViewLayout& layout,
                                                          const std::vector<glm::vec2>& reserved, int w, int h,
                                                          bool keptLinesOnly) {
  std::vector<std::pair<glm::vec2, glm::vec2>> plates;
  for (std::size_t i = 0; i < blocks.size() && i < layout.origins.size(); ++i) {
    TextBlock shown = blocks[i];
    if (shown.lines.size() > layout.lines[i]) shown.lines.resize(layout.lines[i]);
    if (shown.lines.empty()) continue;
    if (keptLinesOnly) shown.minSize.y = 0.0f;  // as tall as the lines it keeps (minSize: all of them)
    const glm::vec2 size(std::max(reserved[i].x, blockSize(shown).x), blockSize(shown).y);
    const glm::vec2 lo = layout.origins[i], hi = lo + size;
    if (lo.x >= 0.0f && lo.y >= 0.0f && hi.x <= float(w) && hi.y <= float(h)) plates.emplace_back(lo, hi);
  }
  return plates;
}

// Each block as large as it gets over the frames `samples` (its minSize;
// the longest of its line lists): blocksOf(frame) gives a frame's blocks.
template <typename BlocksOf>
std::vector<TextBlock> widestBlocks(const BlocksOf& blocksOf, const std::vector<FrameOrientations>& samples,
                                    float viewWidth) {
  std::vector<TextBlock> widest = blocksOf(samples[0]);
  for (const auto& f : samples) {
    std::vector<TextBlock> b = blocksOf(f);
    for (std::size_t i = 0; i < b.size(); ++i) {
      glm::vec2 size = blockSize(b[i]);
      size.x = std::min(size.x * 1.06f, 0.96f * viewWidth);  // digits vary from frame to frame
      widest[i].minSize = glm::max(widest[i].minSize, size);
      if (b[i].lines.size() > widest[i].lines.size()) widest[i].lines = b[i].lines;
    }
  }
  return widest;
}

}  // namespace

// Before the first frame: every block's size over the clip (measured at its
// start and end, and each caption), then where it goes (clip_layout).
void SceneDrawer::layOut(const RollingModel& model) {
  const Rects r = rects();
  // A portrait frame's text is as tall as the rule asks (bodyTextPx) in a
  // narrow view: rather than shrink the subject into a strip, the window
  // keeps over half of each axis and text gives up its later lines.
  const double minWindow = compactText(int(spec_.render.width), int(spec_.render.height)) ? 1.1 : 0.6;
  const double L = model.path->length();
  std::vector<FrameOrientations> samples(2);
  samples[1].current.s = L;
  for (auto& f : samples)
    if (spec_.render.strobe > 1) f.strobe.resize(std::size_t(spec_.render.strobe));
  for (std::size_t k = 1; k < spec_.segments.size(); ++k) {
    FrameOrientations f = samples[1];
    f.story.segment = k;
    samples.push_back(f);
  }
  if (r.ball.width > 0 && layOutBallView(model, r, minWindow, samples)) return layOut(model);
  if (twin_ && layOutTwinView(r, minWindow, samples)) return layOut(model);
}

// The ball view's text, and the window its camera frames the subject into;
// true where a caption moved below the views (lay out again).
bool SceneDrawer::layOutBallView(const RollingModel& model, const Rects& r, double minWindow,
                                 const std::vector<FrameOrientations>& samples) {
  const double L = model.path->length();
  // The arc lengths the clip shows, about two per ball radius, each with
  // its settled camera and (after a storyboard's cut) the previous one.
  // A camera that orbits with the ball sweeps the path across the view: as
  // many samples as the budget allows.
  // A figure's still: that one arc length.
  const int count = camera_->orbits() ? 480 : int(std::clamp(std::ceil(L / (0.5 * model.ballRadius)), 48.0, 240.0));
  std::vector<double> shownS;
  for (int i = 0; i < count && !stillAt_; ++i) shownS.push_back(L * i / (count - 1));
  if (stillAt_) shownS.push_back(std::clamp(*stillAt_, 0.0, L));
  // The ball view's edges inside the frame (an inset lies over the view,
  // not beside it).
  if (!r.inset)
    camera_->setInnerEdges({r.ball.x > 0, r.ball.x + r.ball.width < int(spec_.render.width),
                            r.ball.y + r.ball.height<int(spec_.render.height), r.ball.y> 0});
  const std::vector<TextBlock> blocks = widestBlocks(
      [&](const FrameOrientations& f) { return ballBlocks(f, float(r.ball.width)); }, samples, float(r.ball.width));
  for (const TextBlock& b : blocks) ballReserved_.push_back(b.minSize);
  auto occupancyFor = [&](const NdcWindow& window) {
    camera_->setWindow(window);
    Occupancy occupancy(r.ball.width, r.ball.height);
    // An inset twin covers that corner of the ball view.
    if (r.inset)
      occupancy.rect(glm::vec2(r.twin.x - r.ball.x, r.twin.y - r.ball.y),
                     glm::vec2(r.twin.x - r.ball.x + r.twin.width, r.twin.y - r.ball.y + r.twin.height));
    glm::mat4 marked(0.0f);
    for (const double s : shownS) {
      StoryPlace story = motion::storyPlaceAt(model, s);
      std::vector<StoryPlace> places{story};
      if (story.segment > 0 && !stillAt_) places.push_back({story.segment, 0.0, story.duration});
      for (const StoryPlace& place : places) {
        const render::View v = camera_->ballCamera(0, 0, r.ball.width, r.ball.height, s, place);
        const glm::mat4 clipFromWorld = v.camera.clipFromView * v.camera.viewFromWorld;
        // The path once per camera; a camera that follows the ball sweeps
        // the path across the whole view, so only the ball counts there.
        ball_->markImportant(occupancy, v, s, clipFromWorld != marked && !camera_->follows(place));
        marked = clipFromWorld;
      }
    }
    return occupancy;
  };
  // A figure's subject takes at least half of its view's shorter side
  // (docs/figures.md): text that finds no room beside it is left out (and
  // named) rather than shrink it further. (A strobe's figure keeps the
  // clip's framing and its text; several surfaces': the stretch that shows
  // the still frames it.)
  // The subject: the surface as drawn and the ball; a plane's board, cut
  // to the path, is no subject of its own: there the ball, its path and
  // its trail (the occupancy) are.
  SubjectShare subject;
  if (stillAt_) subject.least = kFigureSubjectShare;
  if (stillAt_ && !ball_->surfaceIsBoard()) {
    const double s = std::clamp(*stillAt_, 0.0, L);
    subject.boundsFor = [&, s](const NdcWindow& window) {
      camera_->setWindow(window);
      const render::View v = camera_->ballCamera(0, 0, r.ball.width, r.ball.height, s, motion::storyPlaceAt(model, s));
      return ball_->subjectBounds(v, s);
    };
  }
  camera_->setCloseInShare(0.0);
  ballLayout_ =
      layoutView(r.ball.width, r.ball.height, blocks, occupancyFor, camera_->fixedByScene(), minWindow, subject);
  closeInBesideText(blocks, r, occupancyFor);
  camera_->setWindow(ballLayout_.window);
  if (moveCaptionsBelow(ballLayout_, blocks, float(r.ball.width))) return true;
  // A figure's block that found no room beside a subject of half the view
  // is left out (and named) rather than put over the subject.
  if (subject.least > 0.0)
    for (std::size_t i = 0; i < ballLayout_.found.size(); ++i)
      if (!ballLayout_.found[i]) ballLayout_.lines[i] = 0, ballLayout_.found[i] = true;
  // A figure's subject fills the room its text leaves: the layout narrows
  // the window by a column or a band at a time, and only as far as the
  // text needs; the largest rectangle clear of the placed plates (by the
  // subject's own shape, a gap of an em) shows it larger.
  // (Only where every block found its place: one that did not is put
  // where the subject leaves room when the still is drawn.)
  const bool allPlaced = std::all_of(ballLayout_.found.begin(), ballLayout_.found.end(), [](bool f) { return f; });
  if (figure() && !camera_->fixedByScene() && !r.inset && allPlaced) {
    const auto [lo, hi] = occupancyFor(ballLayout_.window).bounds();
    const float aspect = hi.x > lo.x && hi.y > lo.y ? (hi.x - lo.x) / (hi.y - lo.y) : 1.0f;
    const auto plates = placedPlates(blocks, ballLayout_, ballReserved_, r.ball.width, r.ball.height, true);
    const NdcWindow grown = clearWindow(r.ball.width, r.ball.height, plates, text(), aspect);
    auto scale = [&](const NdcWindow& win) {
      return std::min((win.x1 - win.x0) * r.ball.width / aspect, (win.y1 - win.y0) * r.ball.height);
    };
    if (scale(grown) > scale(ballLayout_.window)) ballLayout_.window = grown;
    camera_->setWindow(ballLayout_.window);
  }
  return false;
}

// Segments framed closer than the whole clip (a small ball) take only the
// room the text leaves: the text is laid out beside the whole clip's
// framing, and the closer views go as far of the way as clears every plate.
void SceneDrawer::closeInBesideText(const std::vector<TextBlock>& blocks, const Rects& r,
                                    const std::function<Occupancy(const NdcWindow&)>& occupancyFor) {
  if (!camera_->mayCloseIn()) return;
  camera_->setWindow(ballLayout_.window);
  const auto plates = placedPlates(blocks, ballLayout_, ballReserved_, r.ball.width, r.ball.height, false);
  for (const double share : {1.0, 0.75, 0.5, 0.25, 0.0}) {
    camera_->setCloseInShare(share);
    const Occupancy closer = occupancyFor(ballLayout_.window);
    if (share == 0.0 ||
        std::none_of(plates.begin(), plates.end(), [&](const auto& p) { return closer.anyIn(p.first, p.second); }))
      return;
  }
}

// The twin view's text, and the window its camera frames the sphere into;
// true where a caption moved below the views (lay out again).
bool SceneDrawer::layOutTwinView(const Rects& r, double minWindow, const std::vector<FrameOrientations>& samples) {
  const std::vector<TextBlock> blocks =
      widestBlocks([&](const FrameOrientations& f) { return twinBlocks(f, float(r.twin.width), r.inset); }, samples,
                   float(r.twin.width));
  for (const TextBlock& b : blocks) twinReserved_.push_back(b.minSize);
  auto occupancyFor = [&](const NdcWindow& window) {
    twin_->setWindow(window);
    render::DrawList scratch;
    scratch.width = int(spec_.render.width);
    scratch.height = int(spec_.render.height);
    render::View v;
    v.width = r.twin.width;
    v.height = r.twin.height;
    scratch.views.push_back(v);
    FrameOrientations f;
    twin_->add(scratch, f, 0, camera_->aimAt(StoryPlace{}, r.twin.width, r.twin.height, 0.0));
    Occupancy occupancy(r.twin.width, r.twin.height);
    twin_->markImportant(occupancy, scratch.views[0]);
    return occupancy;
  };
  twinLayout_ = layoutView(r.twin.width, r.twin.height, blocks, occupancyFor, false, minWindow);
  if (spec_.render.layout == scene::RenderLayout::Twin && moveCaptionsBelow(twinLayout_, blocks, float(r.twin.width)))
    return true;
  // A figure's sphere fills the room its text leaves: the window grows
  // from the layout's (which keeps the ball's gap of 2 em) to the largest
  // rectangle clear of the plates, less a margin of 0.9 of a line (about
  // 1.3 em) all round where the axis and pole labels lie against it.
  if (twin_->closeLabels() && !r.inset) {
    const auto plates = placedPlates(blocks, twinLayout_, twinReserved_, r.twin.width, r.twin.height, false);
    NdcWindow window = clearWindow(r.twin.width, r.twin.height, plates, 0.25f * text());
    const double marginX = 2.0 * kTwinLabelMargin * text() / r.twin.width;
    const double marginY = 2.0 * kTwinLabelMargin * text() / r.twin.height;
    // (Never under a quarter of the view: a tiny view keeps a sphere.)
    if (window.x1 - window.x0 - 2.0 * marginX >= 0.5 && window.y1 - window.y0 - 2.0 * marginY >= 0.5)
      window = {window.x0 + marginX, window.x1 - marginX, window.y0 + marginY, window.y1 - marginY};
    twinLayout_.window = window;
  }
  twin_->setWindow(twinLayout_.window);
  return false;
}

std::size_t SceneDrawer::stretchOf(std::size_t segment) const {
  std::size_t k = 0;
  while (k + 1 < stretches_.size() && stretches_[k + 1].firstSegment <= segment) ++k;
  return k;
}

FrameOrientations SceneDrawer::inStretch(const FrameOrientations& frame, std::size_t k) const {
  const motion::SurfaceStretch& stretch = stretches_[k];
  FrameOrientations local = frame;
  local.story.segment = frame.story.segment - std::min(frame.story.segment, stretch.firstSegment);
  local.current.s = std::clamp(frame.current.s - stretch.start, 0.0, stretch.end - stretch.start);
  auto cut = [&](std::vector<OrientedSample>& poses) {
    std::erase_if(poses, [&](const OrientedSample& p) { return p.s < stretch.start || p.s > stretch.end; });
    for (OrientedSample& p : poses) p.s -= stretch.start;
  };
  cut(local.trail);
  cut(local.strobe);
  local.cuts.clear();
  return local;
}

render::DrawList SceneDrawer::draw(const FrameOrientations& frame) const {
  if (parts_.empty()) return drawList(frame, frame);
  const std::size_t k = stretchOf(frame.story.segment);
  return parts_[k]->drawList(inStretch(frame, k), frame);
}

std::optional<SceneDrawer::Fade> SceneDrawer::fadeAt(const FrameOrientations& frame) const {
  const std::size_t k = parts_.empty() ? 0 : stretchOf(frame.story.segment);
  if (k == 0 || frame.story.segment != stretches_[k].firstSegment) return std::nullopt;
  const scene::SegmentSpec& segment = spec_.segments[frame.story.segment];
  if (segment.transition != scene::SegmentSpec::Transition::Fade || k > frame.cuts.size()) return std::nullopt;
  // The segment's first frame (0 s) shows the old view whole.
  const double weight = 1.0 - frame.story.seconds / segment.fadeSeconds;
  if (!(weight > 0.0 && weight <= 1.0)) return std::nullopt;
  // The previous surface as the ball left it: its last segment at its end.
  const motion::SurfaceStretch& previous = stretches_[k - 1];
  FrameOrientations left;
  left.current = {previous.end, frame.cuts[k - 1].q};
  for (const OrientedSample& p : frame.trail)
    if (p.s <= previous.end) left.trail.push_back(p);
  left.trail.push_back(left.current);
  left.story.segment = stretches_[k].firstSegment - 1;
  left.story.duration = frame.story.duration;
  left.story.seconds = 1e300;  // settled: long after that segment began
  return Fade{parts_[k - 1]->drawList(inStretch(left, k - 1), left), weight};
}

bool SceneDrawer::cameraMoving(const StoryPlace& story) const {
  if (parts_.empty()) return camera_->moving(story);
  const std::size_t k = stretchOf(story.segment);
  StoryPlace local = story;
  local.segment -= stretches_[k].firstSegment;
  return parts_[k]->cameraMoving(local);
}

std::vector<std::string> SceneDrawer::cameraWarnings() const {
  if (parts_.empty()) return camera_->hiddenWarnings();
  // A stretch names its segments from 1 and its times from its own start.
  std::vector<std::string> out;
  for (std::size_t k = 0; k < parts_.size(); ++k)
    for (std::string w : parts_[k]->cameraWarnings()) {
      for (std::size_t j = stretches_[k].endSegment - stretches_[k].firstSegment; j-- > 0;) {
        const std::string local = scene::SceneSpec::segmentKey(j) + ":";
        if (const auto at = w.find(local); at != std::string::npos) {
          w.replace(at, local.size(), scene::SceneSpec::segmentKey(j + stretches_[k].firstSegment) + ":");
          break;
        }
      }
      if (const auto at = w.find("of the clip"); at != std::string::npos)
        w.replace(at, 11, fmt::format("of surface {}'s part of the clip", k));
      out.push_back(std::move(w));
    }
  return out;
}

render::DrawList SceneDrawer::drawList(const FrameOrientations& frame, const FrameOrientations& whole) const {
  render::DrawList list;
  const auto& rs = spec_.render;
  list.width = static_cast<int>(rs.width);
  list.height = static_cast<int>(rs.height);
  list.msaaSamples = static_cast<int>(rs.msaa);
  list.transparent = rs.transparent;

  // A segment's title replaces render.title while it plays; the band stays
  // for the whole clip when any title is set, so the views never jump.
  const scene::SegmentSpec* segment =
      spec_.segments.empty() ? nullptr : &spec_.segments[std::min(frame.story.segment, spec_.segments.size() - 1)];
  if (titleBand_) {
    const std::string& title = segment && segment->title ? *segment->title : rs.title;
    addTitleBand(list, shownTitle(title), text(), titleLines_, leastText(), figure());
    noteLeftOut(list, {title}, {shownTitle(title)});
  }
  // The caption band before the views (bold at the body size, never under
  // a figure's least size): the twin stays the last view.
  if (captionBandLines_ > 0)
    addCaptionBand(list, captionAt(frame.story), std::max(text(), leastText()), captionBandLines_, kCaptionColor);
  addViews(list, frame, whole);
  return list;
}

void SceneDrawer::addViews(render::DrawList& list, const FrameOrientations& frame,
                           const FrameOrientations& whole) const {
  const Rects r = rects();
  const double s = frame.current.s;
  // A still's blocks keep off what this frame draws (the layout, made for
  // the whole clip, may have found no room for them).
  auto place = [&](std::vector<TextBlock> blocks, const std::vector<glm::vec2>& reserved, const ViewLayout& layout,
                   int view, const Occupancy* subject) {
    const std::size_t n = std::min(blocks.size(), layout.origins.size());
    std::vector<std::vector<std::string>> meant;
    for (const TextBlock& b : blocks) meant.push_back(wholeLines(b));
    blocks.resize(n);
    meant.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      if (blocks[i].lines.size() > layout.lines[i]) blocks[i].lines.resize(layout.lines[i]);
      blocks[i].minSize = glm::vec2(reserved[i].x, blockSize(blocks[i]).y);
    }
    const std::vector<glm::vec2> origins =
        subject ? keepBlocksClear(list, view, blocks, layout.origins, *subject) : layout.origins;
    for (std::size_t i = 0; i < n; ++i) {
      addTextBlock(list, blocks[i], origins[i], view);
      noteLeftOut(list, meant[i], wholeLines(blocks[i]));
    }
  };
  // A still (a strobe) is read at leisure: its world-anchored labels (axis
  // and pole labels, the marks' numbers) move off the arrows, the paths and
  // the text (label_placement.hpp); in a clip they keep their places.
  const bool still = frame.still || !frame.strobe.empty();
  if (r.ball.width > 0) {
    render::View v = camera_->ballCamera(r.ball.x, r.ball.y, r.ball.width, r.ball.height, s, frame.story);
    list.views.push_back(v);
    const int view = int(list.views.size()) - 1;
    const std::size_t firstLabel = list.labels.size();
    const glm::vec3 eye = v.camera.position;
    ball_->add(list, frame, view,
               camera_->cutsAway(frame.story) ? std::optional<geometry::Vec3>(geometry::Vec3(eye.x, eye.y, eye.z))
                                              : std::nullopt);
    Occupancy ball(v.width, v.height);
    if (still) ball_->markImportant(ball, v, s, false);
    place(ballBlocks(frame, float(r.ball.width)), ballReserved_, ballLayout_, view, still ? &ball : nullptr);
    if (still) keepLabelsClearNoting(list, view, firstLabel, false);
  }
  if (twin_) {
    render::View twin;
    twin.x = r.twin.x;
    twin.y = r.twin.y;
    twin.width = r.twin.width;
    twin.height = r.twin.height;
    twin.frame = r.inset;
    list.views.push_back(twin);
    const int view = int(list.views.size()) - 1;
    // "linked": the twin looks along the ball camera's direction, so the
    // marker and the Bloch arrow point the same way on screen; "fixed": the
    // first shot's direction (at s = 0) for the whole clip.
    const StoryPlace story = spec_.render.twinCameraFixed ? StoryPlace{} : frame.story;
    const std::size_t firstLabel = list.labels.size();
    twin_->add(list, whole, view,
               camera_->aimAt(story, twin.width, twin.height, spec_.render.twinCameraFixed ? 0.0 : s));
    Occupancy sphere(twin.width, twin.height);
    if (still) twin_->markImportant(sphere, list.views[std::size_t(view)]);
    place(twinBlocks(frame, float(twin.width), r.inset), twinReserved_, twinLayout_, view, still ? &sphere : nullptr);
    if (still) keepLabelsClearNoting(list, view, firstLabel, twin_->closeLabels());
  }
}

render::View SceneDrawer::ballCamera(const StoryPlace& story, double s) const {
  if (!parts_.empty()) {
    const std::size_t k = stretchOf(story.segment);
    StoryPlace local = story;
    local.segment -= stretches_[k].firstSegment;
    const motion::SurfaceStretch& stretch = stretches_[k];
    return parts_[k]->ballCamera(local, std::clamp(s - stretch.start, 0.0, stretch.end - stretch.start));
  }
  const Rects r = rects();
  if (r.ball.width <= 0) return {};
  return camera_->ballCamera(r.ball.x, r.ball.y, r.ball.width, r.ball.height, s, story);
}

}  // namespace rollspin::draw
