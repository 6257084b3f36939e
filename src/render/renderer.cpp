// The renderer's facade and its frame: the views' items gathered and their
// shadow maps drawn first, the retained layer's plan (layer_plan.hpp)
// carried out, the meshes a frame no longer names evicted. The passes live
// in their own files (see renderer_impl.hpp).
#include "render/renderer.hpp"

#include <algorithm>

#include "core/error.hpp"
#include "core/stage_log.hpp"
#include "render/renderer_impl.hpp"

namespace rollspin::render {

ImageHistory::ImageHistory() = default;
ImageHistory::~ImageHistory() = default;
ImageHistory::ImageHistory(ImageHistory&&) noexcept = default;
ImageHistory& ImageHistory::operator=(ImageHistory&&) noexcept = default;
void ImageHistory::reset() { state_.reset(); }

void Renderer::Impl::render(const DrawList& list, media::Image& image, ImageHistory::State* history) {
  if (list.width <= 0 || list.height <= 0)
    throw badInput({}, "image size {}x{}: expected positive width and height", list.width, list.height);
  if (targets.ensure(list.width, list.height, std::max(1, list.msaaSamples))) captures.clear();
  // Shadow maps first: binding another framebuffer makes llvmpipe run the
  // scene binned so far, so a shadow pass between the scene's clear and its
  // draws would make the clear a separate trip through all the samples in
  // memory instead of a per-tile fill just before the tile is drawn.
  std::vector<ViewItems> perView(list.views.size());
  std::size_t shadowMapsUsed = 0;
  for (std::size_t i = 0; i < list.views.size(); ++i) {
    ViewItems& vi = perView[i];
    vi.arrowMaterials.reserve(list.arrows.size());
    vi.items = drawablesOf(list, static_cast<int>(i), vi.arrowMaterials, caches);
    if (!list.views[i].light.shadow) continue;
    StageLog::instance().record("shadow-map");
    vi.shadowMap = &shadowMaps.at(shadowMapsUsed++);
    vi.shadow = shadowPass(list.views[i], vi.items, *vi.shadowMap, caches, programs, streams);
  }
  // Wait for the shadow maps to be drawn: a texture that a scene still in
  // flight renders into counts as busy, and binding it for sampling would
  // make llvmpipe flush the scene being binned in the middle of the frame
  // (measured: 10 ms of a 1080p frame, the main scene's tiles making two
  // trips through memory).
  if (shadowMapsUsed > 0) glFinish();
  image.width = list.width;
  image.height = list.height;
  // What the image holds, if its history knows; the history itself
  // forgets until this frame is done (a frame that throws halfway leaves
  // pixels it does not describe).
  const std::size_t bytes = static_cast<std::size_t>(list.width) * list.height * 4;
  ImageHistory::State known;
  if (history != nullptr) {
    if (image.rgba.size() == bytes && history->pixels == image.rgba.data()) known = std::move(*history);
    *history = {};
  }
  image.rgba.resize(bytes);  // reused across frames

  const LayerPlan plan = planLayer(layer.memory, list, retainLayers, itemBounds(caches, list));
  if (plan.step == LayerStep::ServedLayer && !plan.changes.empty())
    layer.update(drawing(), readback, list, perView, plan.changes, plan.fresh);
  if (plan.step == LayerStep::NewLayer) layer.build(drawing(), readback, list, perView);
  remember(layer.memory, plan, list);
  if (plan.overLayer()) {
    std::vector<PixelRect> drawn =
        layer.drawOver(drawing(), readback, list, perView, plan.fresh, image, history != nullptr ? &known : nullptr);
    if (history != nullptr) *history = {layer.identity(), layer.version(), std::move(drawn), image.rgba.data()};
    ++stats.retainedFrames;
  } else {
    captures.clear();  // no layer: a camera move, most likely, which they would not survive
    targets.clear(list, false);
    drawWhole(drawing(), list, perView);
    readback.pixels(list, image, PixelRect{0, 0, list.width, list.height}, targets.sceneFbo);
    ++stats.wholeFrames;
  }
  if (const GLenum err = glGetError(); err != GL_NO_ERROR)
    throw runtimeError({}, "OpenGL error 0x{:x} while rendering a {}x{} image ({})", err, list.width, list.height,
                       context.describe());
  caches.evictUnused();
}

Renderer::Renderer(GlContext& context, const ShaderLibrary& shaders)
    : impl_(std::make_unique<Impl>(context, shaders)) {}
Renderer::~Renderer() = default;
media::Image Renderer::render(const DrawList& list) {
  media::Image image;
  impl_->render(list, image);
  return image;
}
void Renderer::render(const DrawList& list, media::Image& image) { impl_->render(list, image); }
void Renderer::render(const DrawList& list, media::Image& image, ImageHistory& history) {
  if (!history.state_) history.state_ = std::make_unique<ImageHistory::State>();
  impl_->render(list, image, history.state_.get());
}
void Renderer::renderWithDepth(const DrawList& list, media::Image& image, std::vector<float>& depth) {
  // The depth of this list alone, drawn whole: no retained layer in between.
  const Impl::RetainLayersOff drawnWhole(*impl_);
  impl_->render(list, image);
  readDepth(impl_->targets.sceneFbo, impl_->targets.width, impl_->targets.height, depth);
}

void Renderer::setRetainLayers(bool on) { impl_->setRetainLayers(on); }

void Renderer::Impl::setRetainLayers(bool on) {
  retainLayers = on;
  if (!on) layer.memory = {};
}
const RenderStats& Renderer::stats() const { return impl_->stats; }

}  // namespace rollspin::render
