// See layer_key.hpp.
#include "render/layer_key.hpp"

#include <algorithm>
#include <type_traits>
#include <utility>

namespace rollspin::render {
namespace {

// Whether `items`' static ones are `kept`, in order.
template <typename Item>
bool sameItems(const std::vector<Item>& kept, const std::vector<Item>& items) {
  std::size_t n = 0;
  for (const Item& item : items) {
    if (item.dynamic) continue;
    if (n == kept.size() || !(kept[n] == item)) return false;
    ++n;
  }
  return n == kept.size();
}

// Pairs the kept static items with the new ones, in order (a longest
// common subsequence under `pairs`): an item inserted or removed in the
// middle (a line's first settled prefix, a new caption line) leaves the
// others paired. Returns, for each new item, its partner's index or -1;
// `keptPaired` says which kept items found one.
template <typename Item, typename Pairs>
std::vector<int> alignItems(const std::vector<Item>& kept, const std::vector<const Item*>& now, Pairs pairs,
                            std::vector<bool>& keptPaired) {
  const std::size_t n = kept.size(), m = now.size();
  std::vector<int> best((n + 1) * (m + 1), 0);  // best[i*(m+1)+j]: LCS of kept[i…], now[j…]
  for (std::size_t i = n; i-- > 0;)
    for (std::size_t j = m; j-- > 0;)
      best[i * (m + 1) + j] = pairs(kept[i], *now[j])
                                  ? best[(i + 1) * (m + 1) + j + 1] + 1
                                  : std::max(best[(i + 1) * (m + 1) + j], best[i * (m + 1) + j + 1]);
  std::vector<int> partner(m, -1);
  keptPaired.assign(n, false);
  for (std::size_t i = 0, j = 0; i < n && j < m;) {
    if (pairs(kept[i], *now[j]) && best[i * (m + 1) + j] == best[(i + 1) * (m + 1) + j + 1] + 1) {
      partner[j] = static_cast<int>(i);
      keptPaired[i] = true;
      ++i, ++j;
    } else if (best[(i + 1) * (m + 1) + j] >= best[i * (m + 1) + j + 1]) {
      ++i;
    } else {
      ++j;
    }
  }
  return partner;
}

// The labels a layer holds, in order (see staticPartOf).
std::vector<LabelItem> staticLabelsOf(const std::vector<LabelItem>& labels) {
  std::vector<LabelItem> out;
  for (const LabelItem& l : labels)
    if (auto part = staticPartOf(l)) out.push_back(std::move(*part));
  return out;
}

}  // namespace

std::optional<LabelItem> staticPartOf(const LabelItem& label) {
  if (!label.dynamic) return label;
  if (label.staticPrefixBytes == 0 || label.staticPrefixBytes >= label.text.size() || label.align != Align::Left)
    return std::nullopt;
  LabelItem part = label;
  part.text.resize(label.staticPrefixBytes);
  part.dynamic = false;
  part.staticPrefixBytes = 0;
  return part;
}

View withoutShadowBox(View v) {
  v.light.shadowCenter = glm::vec3(0.0f);
  v.light.shadowRadius = 0.0f;
  v.light.shadowSoftness = 0.0f;
  return v;
}

bool sameStatic(const StaticKey& k, const DrawList& list) {
  if (k.width != list.width || k.height != list.height || k.samples != std::max(1, list.msaaSamples) ||
      k.transparent != list.transparent || k.views.size() != list.views.size())
    return false;
  for (std::size_t i = 0; i < k.views.size(); ++i)
    if (k.stale[i] || !(k.views[i] == withoutShadowBox(list.views[i]))) return false;
  return sameItems(k.meshes, list.meshes) && sameItems(k.arrows, list.arrows) &&
         sameItems(k.polylines, list.polylines) && k.labels == staticLabelsOf(list.labels);
}


StaticKey staticKeyOf(const DrawList& list) {
  StaticKey k;
  k.width = list.width;
  k.height = list.height;
  k.samples = std::max(1, list.msaaSamples);
  k.transparent = list.transparent;
  for (const View& v : list.views) k.views.push_back(withoutShadowBox(v));
  k.stale.assign(list.views.size(), false);
  for (const MeshItem& m : list.meshes)
    if (!m.dynamic) k.meshes.push_back(m);
  for (const ArrowItem& a : list.arrows)
    if (!a.dynamic) k.arrows.push_back(a);
  for (const PolylineItem& p : list.polylines)
    if (!p.dynamic) k.polylines.push_back(p);
  k.labels = staticLabelsOf(list.labels);
  return k;
}

std::optional<std::vector<bool>> freshViews(const StaticKey& k, const DrawList& list) {
  if (k.width != list.width || k.height != list.height || k.samples != std::max(1, list.msaaSamples) ||
      k.transparent != list.transparent || k.views.size() != list.views.size())
    return std::nullopt;
  std::vector<bool> fresh(k.views.size());
  for (std::size_t i = 0; i < k.views.size(); ++i)
    fresh[i] = k.stale[i] || !(k.views[i] == withoutShadowBox(list.views[i]));
  return fresh;
}

namespace {

// What layerChanges compares against and marks: the list, its fresh views
// (not compared: drawn whole), the items' screen bounds, and the grid of
// tiles that changed.
struct LayerDiff {
  const DrawList& list;
  const std::vector<bool>& fresh;
  const ItemBounds& bounds;
  TileGrid& grid;

  // Whether the item's view is compared (in none, or not a fresh one).
  template <typename Item>
  [[nodiscard]] bool compared(const Item& item) const {
    return item.view < 0 || static_cast<std::size_t>(item.view) >= fresh.size() ||
           !fresh[static_cast<std::size_t>(item.view)];
  }
  // The kept items that are compared.
  template <typename Item>
  [[nodiscard]] std::vector<Item> keptOf(const std::vector<Item>& items) const {
    std::vector<Item> out;
    for (const Item& item : items)
      if (compared(item)) out.push_back(item);
    return out;
  }
  // The list's static items that are compared.
  template <typename Item>
  [[nodiscard]] std::vector<const Item*> staticOf(const std::vector<Item>& items) const {
    std::vector<const Item*> out;
    for (const Item& item : items)
      if (!item.dynamic && compared(item)) out.push_back(&item);
    return out;
  }
  // The view `index` and its clipFromWorld; none for no view.
  [[nodiscard]] std::optional<std::pair<const View*, glm::mat4>> viewOf(int index) const {
    if (index < 0 || static_cast<std::size_t>(index) >= list.views.size()) return std::nullopt;
    const View& v = list.views[static_cast<std::size_t>(index)];
    return std::make_pair(&v, v.camera.clipFromView * v.camera.viewFromWorld);
  }
};

// Meshes: an opaque one is in the snapshot and must stay as it is (false:
// build the layer again); a translucent one that changed, came or went
// marks its old and new bounds.
bool markMeshChanges(const LayerDiff& diff, const std::vector<MeshItem>& kept) {
  std::vector<bool> keptPaired;
  const auto meshes = diff.staticOf(diff.list.meshes);
  const auto meshPartner = alignItems(
      kept, meshes,
      [](const MeshItem& a, const MeshItem& b) {
        return a == b || (a.view == b.view && a.material.opacity < 1.0f && b.material.opacity < 1.0f);
      },
      keptPaired);
  auto addMesh = [&](const MeshItem& m) {
    const auto v = diff.viewOf(m.view);
    if (!v || !m.mesh) return true;  // drawn in no view: nothing to redraw
    if (m.material.opacity >= 1.0f) return false;
    std::vector<PixelRect> rects;
    diff.bounds.mesh(m, *v->first, v->second, rects);
    for (const PixelRect& r : rects) diff.grid.add(r);
    return true;
  };
  for (std::size_t j = 0; j < meshes.size(); ++j) {
    const int i = meshPartner[j];
    if (i >= 0 && kept[static_cast<std::size_t>(i)] == *meshes[j]) continue;
    if (!addMesh(*meshes[j]) || (i >= 0 && !addMesh(kept[static_cast<std::size_t>(i)]))) return false;
  }
  for (std::size_t i = 0; i < kept.size(); ++i)
    if (!keptPaired[i] && !addMesh(kept[i])) return false;
  return true;
}

// Lines: a pair with the same look whose points share a prefix (a line
// that grew or shrank) differs only from the last shared point on (round
// joins: a segment's capsule ends at its points).
void markLineChanges(const LayerDiff& diff, const std::vector<PolylineItem>& kept) {
  std::vector<bool> keptPaired;
  const auto lines = diff.staticOf(diff.list.polylines);
  const auto linePartner = alignItems(
      kept, lines,
      [](const PolylineItem& a, const PolylineItem& b) {
        return a.view == b.view && a.color == b.color && a.widthPx == b.widthPx && a.depthTested == b.depthTested;
      },
      keptPaired);
  auto addLine = [&](const PolylineItem& p, std::size_t first) {
    const auto v = diff.viewOf(p.view);
    if (v) addSegmentBounds(p, *v->first, v->second, first, diff.grid);
  };
  for (std::size_t j = 0; j < lines.size(); ++j) {
    const PolylineItem& now = *lines[j];
    if (linePartner[j] < 0) {
      addLine(now, 0);
      continue;
    }
    const PolylineItem& before = kept[static_cast<std::size_t>(linePartner[j])];
    if (before == now) continue;
    const std::size_t shared = std::min(before.points.size(), now.points.size());
    const bool prefix =
        std::equal(before.points.begin(), before.points.begin() + std::ptrdiff_t(shared), now.points.begin());
    const std::size_t first = prefix && shared > 0 ? shared - 1 : 0;
    addLine(before, first);
    addLine(now, first);
  }
  for (std::size_t i = 0; i < kept.size(); ++i)
    if (!keptPaired[i]) addLine(kept[i], 0);
}

// Labels: old and new bounds of each that changed, came or went.
void markLabelChanges(const LayerDiff& diff, const std::vector<LabelItem>& kept) {
  std::vector<bool> keptPaired;
  std::vector<LabelItem> staticLabels;
  for (LabelItem& l : staticLabelsOf(diff.list.labels))
    if (diff.compared(l)) staticLabels.push_back(std::move(l));
  std::vector<const LabelItem*> labels;
  for (const LabelItem& l : staticLabels) labels.push_back(&l);
  const auto labelPartner = alignItems(
      kept, labels, [](const LabelItem& a, const LabelItem& b) { return a.view == b.view; }, keptPaired);
  auto addLabel = [&](const LabelItem& l) {
    if (l.view < 0) {
      diff.grid.add(diff.bounds.label(l, nullptr, glm::mat4(1.0f)));
    } else if (const auto v = diff.viewOf(l.view)) {
      diff.grid.add(diff.bounds.label(l, v->first, v->second));
    }
  };
  for (std::size_t j = 0; j < labels.size(); ++j) {
    const int i = labelPartner[j];
    if (i >= 0 && kept[static_cast<std::size_t>(i)] == *labels[j]) continue;
    addLabel(*labels[j]);
    if (i >= 0) addLabel(kept[static_cast<std::size_t>(i)]);
  }
  for (std::size_t i = 0; i < kept.size(); ++i)
    if (!keptPaired[i]) addLabel(kept[i]);
}

}  // namespace

std::optional<std::vector<PixelRect>> layerChanges(const StaticKey& k, const DrawList& list,
                                                   const std::vector<bool>& fresh, const ItemBounds& bounds) {
  TileGrid grid(list.width, list.height);
  const LayerDiff diff{list, fresh, bounds, grid};
  // Arrows are opaque meshes: any change builds the layer again.
  {
    const auto keptArrows = diff.keptOf(k.arrows);
    const auto arrows = diff.staticOf(list.arrows);
    if (keptArrows.size() != arrows.size()) return std::nullopt;
    for (std::size_t i = 0; i < arrows.size(); ++i)
      if (!(keptArrows[i] == *arrows[i])) return std::nullopt;
  }
  if (!markMeshChanges(diff, diff.keptOf(k.meshes))) return std::nullopt;
  markLineChanges(diff, diff.keptOf(k.polylines));
  markLabelChanges(diff, diff.keptOf(k.labels));
  return grid.rects();
}

void addSegmentBounds(const PolylineItem& p, const View& v, const glm::mat4& clipFromWorld, std::size_t first,
                      TileGrid& grid) {
  const float margin = 0.7072f * p.widthPx + 2.0f;
  for (std::size_t k = first; k + 1 < p.points.size(); ++k) {
    const glm::vec3 ends[2] = {p.points[k], p.points[k + 1]};
    if ((clipFromWorld * glm::vec4(ends[0], 1.0f)).w <= 1e-6f || (clipFromWorld * glm::vec4(ends[1], 1.0f)).w <= 1e-6f)
      continue;
    grid.add(screenBounds(v, clipFromWorld, ends, 2, margin));
  }
}

}  // namespace rollspin::render
