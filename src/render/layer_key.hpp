// The retained layer's key (render/retained_layers.cpp): the static items and views
// a layer was drawn from, and what a new frame's list changes against it —
// whether the layer serves it as it is, which views must be drawn whole
// (their camera moved), and which tiles an in-place update must
// redraw when only static lines, labels or translucent meshes changed.
// Plain data: no GL. A frame over the layer is byte-identical to the frame
// drawn whole, so these rules only decide how much is redrawn.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "render/draw_list.hpp"
#include "render/screen_bounds.hpp"

namespace rollspin::render {

// What a layer was drawn from: the image's size and samples, the views (the
// shadow box aside) and the static items, in order.
struct StaticKey {
  int width = 0, height = 0, samples = 0;
  bool transparent = false;
  std::vector<View> views;
  std::vector<MeshItem> meshes;
  std::vector<ArrowItem> arrows;
  std::vector<PolylineItem> polylines;
  std::vector<LabelItem> labels;
  // Views whose pixels in the layer are not the key's (a frame drew them
  // whole with another camera and an update may have drawn over them):
  // such a view is drawn whole in every frame until a layer is built.
  std::vector<bool> stale;
  bool operator==(const StaticKey&) const = default;
};

// The shadow box (which follows the ball) shapes only the shadow map,
// which a layer does not use: the re-shade is redrawn per frame.
[[nodiscard]] View withoutShadowBox(View v);

// Whether `list`'s static items and views are the key's, compared in place:
// a frame over a layer pays no copy of the static lines and labels.
[[nodiscard]] bool sameStatic(const StaticKey& k, const DrawList& list);

[[nodiscard]] StaticKey staticKeyOf(const DrawList& list);

// What of a label a retained layer holds: all of a static one, the leading
// words of a left-aligned dynamic one with a static prefix (as a static
// label of its own: laid out alone it puts its glyphs where the whole label
// puts them), nothing of the rest.
[[nodiscard]] std::optional<LabelItem> staticPartOf(const LabelItem& label);

// The views a frame over the layer must draw whole: those whose camera
// (or light, backdrop, place) is not the key's, and the key's stale ones.
// None: the layer cannot serve this list at all (another size, another
// set of views).
[[nodiscard]] std::optional<std::vector<bool>> freshViews(const StaticKey& k, const DrawList& list);

// Dirty 16-pixel tiles, gathered as disjoint rectangles. 16 rather than 32:
// a thin diagonal item (an arrow, a trail) dirties a narrower band, and the
// tiles drawn in samples near edges shrink (measured: a fixed camera's
// 1080p frame redraws 6.1 % of its pixels instead of 7.0 %; every scene of
// the quality table at or below its figure with 32).
struct TileGrid {
  static constexpr int kTile = 16;
  int cols, rows, width, height;
  std::vector<std::uint8_t> dirty;
  TileGrid(int w, int h)
      : cols((w + kTile - 1) / kTile),
        rows((h + kTile - 1) / kTile),
        width(w),
        height(h),
        dirty(static_cast<std::size_t>(cols) * rows, 0) {}
  void add(const PixelRect& r) {
    if (r.empty()) return;
    for (int ty = std::max(0, r.y0 / kTile); ty <= std::min(rows - 1, (r.y1 - 1) / kTile); ++ty)
      for (int tx = std::max(0, r.x0 / kTile); tx <= std::min(cols - 1, (r.x1 - 1) / kTile); ++tx)
        dirty[static_cast<std::size_t>(ty) * cols + tx] = 1;
  }
  [[nodiscard]] std::vector<PixelRect> rects() const { return rectsOfTiles(dirty, cols, rows, kTile, width, height); }
};

// The bounds of a polyline's segments from `first` on, one by one. A
// segment draws the pixels within half a width of it (a capsule,
// line.geom/line.frag), inside this margin around its end points; one
// with an end behind the eye is not drawn (line.geom).
void addSegmentBounds(const PolylineItem& p, const View& v, const glm::mat4& clipFromWorld, std::size_t first,
                      TileGrid& grid);

// Where an item can draw, as the renderer knows it (a mesh's bounds come
// from its uploaded copy, a label's from the font atlas).
struct ItemBounds {
  std::function<void(const MeshItem&, const View&, const glm::mat4& clipFromWorld, std::vector<PixelRect>& out)> mesh;
  // view null: an image-level label
  std::function<PixelRect(const LabelItem&, const View* view, const glm::mat4& clipFromWorld)> label;
};

// When the layer's views (the fresh ones aside), static arrows and static
// opaque meshes hold and only static lines, labels or translucent meshes
// changed (a growing line reached its next checkpoint, a caption or a text
// plate changed), the pixels that can differ between the kept layer and
// the new one: the segments past the common prefix of a line that grew or
// shrank (all segments of a line otherwise changed, added or removed), and
// the old and new bounds of a changed label or translucent mesh. Items of
// fresh views are not compared (those views are drawn whole). The snapshot
// (the static opaque meshes' samples) holds as it is. Empty: nothing
// changed. None: the layer must be built again.
[[nodiscard]] std::optional<std::vector<PixelRect>> layerChanges(const StaticKey& k, const DrawList& list,
                                                                 const std::vector<bool>& fresh,
                                                                 const ItemBounds& bounds);

}  // namespace rollspin::render
