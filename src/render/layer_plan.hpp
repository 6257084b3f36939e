// The retained layer's decision, made once per frame before anything is
// drawn: draw the frame whole, or over the layer kept (as it is, brought up
// to date in place, or built anew). Plain data, no GL: the renderer
// (renderer.cpp) carries the plan out. A frame over the layer is
// byte-identical to the frame drawn whole, so the plan only decides how
// much is redrawn.
#pragma once

#include <optional>
#include <vector>

#include "render/draw_list.hpp"
#include "render/layer_key.hpp"
#include "render/screen_bounds.hpp"

namespace rollspin::render {

// A layer's identity: one object per build (see ImageHistory).
struct LayerIdentity {};

// What the renderer remembers of the frames before.
struct LayerMemory {
  std::optional<StaticKey> layerKey;    // the layer kept: valid while this matches
  std::optional<StaticKey> pendingKey;  // the last frame drawn whole (a layer is built when a second shares it)
  bool lastFrameOverLayer = false;
};

enum class LayerStep {
  DrawWhole,    // no layer serves this frame
  SameLayer,    // the layer serves as it is
  ServedLayer,  // the layer serves, with `changes` redrawn in it first (maybe none) and `fresh` views
  NewLayer,     // a layer is built from this frame's static items, then the frame drawn over it
};

struct LayerPlan {
  LayerStep step = LayerStep::DrawWhole;
  // Per view: drawn whole inside a frame over the layer (its camera moved
  // while another's held). All false but for ServedLayer.
  std::vector<bool> fresh;
  std::vector<PixelRect> changes;  // ServedLayer: the layer's rectangles to redraw in place
  bool rememberPending = false;    // DrawWhole: this frame's static items become the pending key
  [[nodiscard]] bool overLayer() const { return step != LayerStep::DrawWhole; }
};

// Whether two views' rectangles share a pixel.
[[nodiscard]] bool viewsOverlap(const View& a, const View& b);

// Whether no two views of `list` overlap (a layer needs that: an inset's
// clear would come between the views' steps).
[[nodiscard]] bool viewsDisjoint(const DrawList& list);

// The plan for `list`. A layer pays off from the second frame that shares
// it. When the frame before was drawn over a layer, the camera held still
// and only static content changed (a growing line reached a checkpoint, a
// caption changed): a new layer is built at once. Otherwise one is built
// when a second frame shares it. A view whose camera moved while another
// held (a follow camera beside a fixed twin) is "fresh": drawn whole inside
// a frame over the layer, while the views that held use the layer.
[[nodiscard]] LayerPlan planLayer(const LayerMemory& memory, const DrawList& list, bool retain,
                                  const ItemBounds& bounds);

// The memory after `plan` was carried out for `list`.
void remember(LayerMemory& memory, const LayerPlan& plan, const DrawList& list);

}  // namespace rollspin::render
