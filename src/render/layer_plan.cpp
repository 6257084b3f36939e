#include "render/layer_plan.hpp"

#include <algorithm>

namespace rollspin::render {

bool viewsOverlap(const View& a, const View& b) {
  return a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;
}

bool viewsDisjoint(const DrawList& list) {
  for (std::size_t i = 0; i < list.views.size(); ++i)
    for (std::size_t j = i + 1; j < list.views.size(); ++j)
      if (viewsOverlap(list.views[i], list.views[j])) return false;
  return true;
}

LayerPlan planLayer(const LayerMemory& memory, const DrawList& list, bool retain, const ItemBounds& bounds) {
  LayerPlan plan;
  plan.fresh.assign(list.views.size(), false);
  if (!retain || !viewsDisjoint(list)) return plan;
  // Whether `key` serves this list: some view held, and the held views'
  // static items are the key's or changed only as layerChanges allows.
  std::optional<std::vector<PixelRect>> changes;
  auto serves = [&](const StaticKey& key) {
    const std::optional<std::vector<bool>> f = freshViews(key, list);
    if (!f || std::find(f->begin(), f->end(), false) == f->end()) return false;
    changes = layerChanges(key, list, *f, bounds);
    if (changes) plan.fresh = *f;
    return changes.has_value();
  };
  if (memory.layerKey && sameStatic(*memory.layerKey, list)) {
    plan.step = LayerStep::SameLayer;
  } else if (memory.layerKey && serves(*memory.layerKey)) {
    plan.step = LayerStep::ServedLayer;
    plan.changes = std::move(*changes);
  } else if ((memory.pendingKey && serves(*memory.pendingKey) && changes->empty()) || memory.lastFrameOverLayer) {
    plan.step = LayerStep::NewLayer;
    plan.fresh.assign(list.views.size(), false);
  } else {
    plan.fresh.assign(list.views.size(), false);
    plan.rememberPending = true;
  }
  return plan;
}

void remember(LayerMemory& memory, const LayerPlan& plan, const DrawList& list) {
  switch (plan.step) {
    case LayerStep::DrawWhole:
      if (plan.rememberPending) memory.pendingKey = staticKeyOf(list);
      break;
    case LayerStep::SameLayer: break;
    case LayerStep::ServedLayer:
      memory.layerKey = staticKeyOf(list);
      memory.layerKey->stale = plan.fresh;
      memory.pendingKey.reset();
      break;
    case LayerStep::NewLayer:
      memory.layerKey = staticKeyOf(list);
      memory.pendingKey.reset();
      break;
  }
  memory.lastFrameOverLayer = plan.overLayer();
}

}  // namespace rollspin::render
