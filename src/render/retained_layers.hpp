// The retained layer (see retained_layers.cpp for the order a frame is
// drawn in and why): the static items' scene and finished image kept from
// frame to frame, a frame drawn over it (its dirty rectangles redrawn), and
// the layer brought up to date in place. It owns what it keeps and the
// vectors it reuses; every step takes what it draws with (ViewDrawing, the
// readback) as arguments. Renderer-internal.
//   dI/dt ≡ 0 outside the dirty rectangles: a frame over the layer draws
//   there exactly what the layer holds.
#pragma once

#include <cstdint>
#include <deque>
#include <memory>
#include <utility>
#include <vector>

#include "media/image_view.hpp"
#include "render/layer_plan.hpp"
#include "render/readback.hpp"
#include "render/renderer.hpp"
#include "render/view_pass.hpp"

namespace rollspin::render {

// An image's pixels: the layer image `layer` at `version`, except inside
// `written` (a frame's rectangles). A layer's identity is an object of its
// own, which a history keeps alive: it never matches another layer, of this
// renderer or another.
struct ImageHistory::State {
  std::shared_ptr<const LayerIdentity> layer;  // null: unknown
  std::uint64_t version = 0;
  std::vector<PixelRect> written;
  const std::uint8_t* pixels = nullptr;  // the buffer it describes
};

class RetainedLayer {
 public:
  // Draws the static items into the scene, keeping the samples after their
  // opaque meshes, and reads their finished image into the layer's image.
  void build(const ViewDrawing& drawing, Readback& readback, const DrawList& list,
             const std::vector<ViewItems>& perView);
  // A frame over the layer: `image` with the dirty rectangles redrawn;
  // `history` (if known) says what `image` already holds. Returns the
  // rectangles drawn.
  std::vector<PixelRect> drawOver(const ViewDrawing& drawing, Readback& readback, const DrawList& list,
                                  const std::vector<ViewItems>& perView, const std::vector<bool>& fresh,
                                  media::Image& image, const ImageHistory::State* history);
  // The layer brought up to date in place: `rects` redrawn with the static items alone.
  void update(const ViewDrawing& drawing, Readback& readback, const DrawList& list,
              const std::vector<ViewItems>& perView, const std::vector<PixelRect>& rects,
              const std::vector<bool>& fresh);

  [[nodiscard]] const std::shared_ptr<const LayerIdentity>& identity() const { return identity_; }
  [[nodiscard]] std::uint64_t version() const { return version_; }

  LayerMemory memory;  // the keys planLayer compares (layer_plan.hpp)

 private:
  // A frame's lists, and its views drawn whole inside a frame over the layer.
  struct RedrawJob {
    const DrawList& list;
    const std::vector<ViewItems>& perView;
    const std::vector<bool>& fresh;
  };
  void redrawRects(const ViewDrawing& drawing, Readback& readback, const RedrawJob& job,
                   const std::vector<PixelRect>& rects, Items which, media::Image& image,
                   std::vector<PixelRect>* under);

  // Its finished image of the static items, and that image's identity: a
  // new one per build, a new version per update in place, with the
  // rectangles each recent update changed (what an image drawn over an
  // older version must put back besides its own rectangles).
  media::Image image_;
  std::vector<PixelRect> edgeRects_;  // tiles where its opaque meshes cover pixels in part
  std::shared_ptr<const LayerIdentity> identity_;
  std::uint64_t version_ = 0, restorableFrom_ = 0;
  std::deque<std::pair<std::uint64_t, std::vector<PixelRect>>> updates_;
  static constexpr std::size_t kUpdatesKept = 64;
  // What a frame over it restores from it, and the parts outside the fresh
  // views: reused from frame to frame (drawOver, redrawRects).
  std::vector<PixelRect> restoredParts_, splitParts_;
};

// What layerChanges needs to know of the items' extents.
[[nodiscard]] ItemBounds itemBounds(GpuCaches& caches, const DrawList& list);

}  // namespace rollspin::render
