#include "draw/label_placement.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <vector>

#include "draw/clip_layout.hpp"

namespace rollspin::draw {

namespace {

struct Segment {
  glm::vec2 a, b;
  float half;  // half the width drawn along it, in pixels
};

struct Box {
  glm::vec2 lo, hi;
};

float distanceToSegment(glm::vec2 p, const Segment& s) {
  const glm::vec2 d = s.b - s.a;
  const float t = glm::clamp(glm::dot(p - s.a, d) / std::max(glm::dot(d, d), 1e-6f), 0.0f, 1.0f);
  return glm::length(p - (s.a + t * d));
}

bool inside(glm::vec2 p, const Box& b) { return p.x >= b.lo.x && p.x <= b.hi.x && p.y >= b.lo.y && p.y <= b.hi.y; }

// Whether the segments a–b and c–d cross.
bool crossing(glm::vec2 a, glm::vec2 b, glm::vec2 c, glm::vec2 d) {
  auto side = [](glm::vec2 o, glm::vec2 p, glm::vec2 q) {
    return (p.x - o.x) * (q.y - o.y) - (p.y - o.y) * (q.x - o.x);
  };
  const float d1 = side(c, d, a), d2 = side(c, d, b), d3 = side(a, b, c), d4 = side(a, b, d);
  return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0));
}

// The distance between a box and a segment is below `half` when the
// segment enters the box, or a box corner is near the segment, or a
// segment end is near the box.
bool meets(const Box& box, const Segment& s) {
  // A segment whose bounding box, widened by `half` and a pixel more (for
  // rounding), misses the box passes none of the tests below; for most of a
  // label's candidate boxes that is most segments.
  const float reach = s.half + 1.0f;
  if (std::min(s.a.x, s.b.x) - reach > box.hi.x || std::max(s.a.x, s.b.x) + reach < box.lo.x ||
      std::min(s.a.y, s.b.y) - reach > box.hi.y || std::max(s.a.y, s.b.y) + reach < box.lo.y)
    return false;
  if (inside(s.a, box) || inside(s.b, box)) return true;
  const glm::vec2 corners[4] = {box.lo, {box.hi.x, box.lo.y}, box.hi, {box.lo.x, box.hi.y}};
  for (int k = 0; k < 4; ++k) {
    if (crossing(s.a, s.b, corners[k], corners[(k + 1) % 4])) return true;
    if (distanceToSegment(corners[k], s) < s.half) return true;
  }
  for (const glm::vec2 end : {s.a, s.b}) {
    const glm::vec2 nearest = glm::clamp(end, box.lo, box.hi);
    if (glm::length(end - nearest) < s.half) return true;
  }
  return false;
}

// A view's projection into its pixels (y down), with the clip w.
auto projectorOf(const render::View& v, const glm::mat4& clipFromWorld) {
  return [&v, clipFromWorld](const glm::vec3& p, float& w) {
    const glm::vec4 c = clipFromWorld * glm::vec4(p, 1.0f);
    w = c.w;
    return glm::vec2((c.x / c.w * 0.5f + 0.5f) * float(v.width), (0.5f - c.y / c.w * 0.5f) * float(v.height));
  };
}

// The view's projected arrows and paths (PolylineItem::labelsKeepOff).
std::vector<Segment> obstaclesOf(const render::DrawList& list, int view) {
  const render::View& v = list.views[std::size_t(view)];
  const glm::mat4 clipFromWorld = v.camera.clipFromView * v.camera.viewFromWorld;
  const auto project = projectorOf(v, clipFromWorld);
  // The arrows as the renderer builds them (shaft to the neck, a head 2.6
  // shaft radii wide; render/vector_figure), their radii projected at their
  // depth.
  std::vector<Segment> obstacles;
  const float focal = 0.5f * float(v.height) * v.camera.clipFromView[1][1];
  for (const render::ArrowItem& a : list.arrows) {
    if (a.view != view) continue;
    const float length = glm::length(a.tip - a.origin);
    if (length <= 0.0f) continue;
    const glm::vec3 neck = a.tip - (a.tip - a.origin) / length * std::min(0.35f * length, 6.0f * a.shaftRadius);
    float wo = 1.0f, wn = 1.0f, wt = 1.0f;
    const glm::vec2 o = project(a.origin, wo), n = project(neck, wn), t = project(a.tip, wt);
    if (wo <= 1e-4f || wn <= 1e-4f || wt <= 1e-4f) continue;
    const float nearest = std::min({wo, wn, wt});
    obstacles.push_back({o, n, a.shaftRadius * focal / nearest + 1.0f});
    obstacles.push_back({n, t, 2.6f * a.shaftRadius * focal / nearest + 1.0f});
  }
  for (const render::PolylineItem& p : list.polylines) {
    if (p.view != view || !p.labelsKeepOff) continue;
    for (std::size_t k = 0; k + 1 < p.points.size(); ++k) {
      float wa = 1.0f, wb = 1.0f;
      const glm::vec2 a = project(p.points[k], wa), b = project(p.points[k + 1], wb);
      if (wa > 1e-4f && wb > 1e-4f) obstacles.push_back({a, b, 0.5f * p.widthPx + 1.0f});
    }
  }

  return obstacles;
}

// The text blocks' plates in the view's pixels (placed before labels: the
// layout is decided per clip), taken like labels already placed.
template <typename Project>
std::vector<Box> textPlateBoxes(const render::DrawList& list, int view, const Project& project) {
  std::vector<Box> placed;
  for (const render::MeshItem& m : list.meshes) {
    if (m.view != view || !m.textPlate || !m.mesh) continue;
    Box b{glm::vec2(1e30f), glm::vec2(-1e30f)};
    for (const render::Vertex& vertex : m.mesh->vertices) {
      float w = 1.0f;
      const glm::vec2 q = project(glm::vec3(m.worldFromModel * glm::vec4(vertex.position, 1.0f)), w);
      b.lo = glm::min(b.lo, q), b.hi = glm::max(b.hi, q);
    }
    placed.push_back(b);
  }
  return placed;
}

// How many things a box meets (the view's edge and another label count as
// many as every segment together: a label must stay whole and apart).
int labelBoxCost(const Box& box, const render::View& v, const std::vector<Box>& placed,
                 const std::vector<Segment>& obstacles) {
  const int heavy = int(obstacles.size()) + 1;
  int n = 0;
  if (box.lo.x < 0.0f || box.lo.y < 0.0f || box.hi.x > float(v.width) || box.hi.y > float(v.height)) n += heavy;
  for (const Box& b : placed)
    if (box.lo.x < b.hi.x && b.lo.x < box.hi.x && box.lo.y < b.hi.y && b.lo.y < box.hi.y) n += heavy;
  for (const Segment& s : obstacles)
    if (meets(box, s)) ++n;
  return n;
}

// A label's box for an offset from its anchor (in pixels), padded by a
// quarter em (a figure's Bloch labels, set close, by an eighth).
struct LabelBoxAt {
  glm::vec2 anchor;
  float width, pad, shift, sizePx;
  LabelBoxAt(const render::LabelItem& l, glm::vec2 anchor, bool nearestToAnchor)
      : anchor(anchor),
        width(textWidthPx(l.text, l.sizePx, l.bold)),
        pad((nearestToAnchor ? 0.125f : 0.25f) * l.sizePx),
        shift(l.align == render::Align::Left    ? 0.5f * width
              : l.align == render::Align::Right ? -0.5f * width
                                                : 0.0f),
        sizePx(l.sizePx) {}
  [[nodiscard]] Box operator()(glm::vec2 offset) const {
    const glm::vec2 c = anchor + offset + glm::vec2(shift, 0.0f);
    return Box{c - glm::vec2(0.5f * width + pad, 0.5f * sizePx + pad),
               c + glm::vec2(0.5f * width + pad, 0.5f * sizePx + pad)};
  }
};

// The nearest clear offset for a label: its own place first; with
// nearestToAnchor, rings a quarter em apart tried in the order of their
// boxes' distance from the anchor (the clear place whose box is nearest
// the point the label names); then rings half an em apart out to 6 em. None
// where nothing within 6 em is clear.
template <typename Cost>
std::optional<glm::vec2> clearLabelOffset(const render::LabelItem& l, const LabelBoxAt& boxAt, bool nearestToAnchor,
                                          const Cost& cost) {
  glm::vec2 best = l.offsetPx;
  int bestCost = cost(boxAt(best));
  if (nearestToAnchor && bestCost > 0) {
    std::vector<std::pair<float, glm::vec2>> candidates;
    for (float radius = 0.25f; radius <= 6.0f; radius += 0.25f)
      for (int k = 0; k < 48; ++k) {
        const float angle = 2.0f * std::numbers::pi_v<float> * float(k) / 48.0f;
        const glm::vec2 offset = l.offsetPx + radius * l.sizePx * glm::vec2(std::cos(angle), std::sin(angle));
        const Box b = boxAt(offset);
        candidates.emplace_back(glm::length(boxAt.anchor - glm::clamp(boxAt.anchor, b.lo, b.hi)) + 0.01f * radius,
                                offset);
      }
    std::sort(candidates.begin(), candidates.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (const auto& [distance, offset] : candidates) {
      const int c = cost(boxAt(offset));
      if (c < bestCost) best = offset, bestCost = c;
      if (bestCost == 0) break;
    }
  }
  for (float radius = 0.5f; radius <= 6.0f && bestCost > 0; radius += 0.5f)
    for (int k = 0; k < 24 && bestCost > 0; ++k) {
      const float angle = 2.0f * std::numbers::pi_v<float> * float(k) / 24.0f;
      const glm::vec2 offset = l.offsetPx + radius * l.sizePx * glm::vec2(std::cos(angle), std::sin(angle));
      const int c = cost(boxAt(offset));
      if (c < bestCost) {
        best = offset;
        bestCost = c;
      }
    }
  if (bestCost > 0) return std::nullopt;
  return best;
}

// A label moved far from what it names: its anchor and box in pixels.
struct LabelLeader {
  std::size_t label;
  glm::vec2 anchor;
  Box box;
};

// Thin leader lines from each moved label's anchor to its box's edge
// (drawn over everything, at the anchor's depth).
void addLeaderLines(render::DrawList& list, int view, const std::vector<LabelLeader>& leaders,
                    const glm::mat4& clipFromWorld) {
  const render::View& v = list.views[std::size_t(view)];
  const glm::mat4 worldFromClip = glm::inverse(clipFromWorld);
  for (const LabelLeader& leader : leaders) {
    const render::LabelItem& l = list.labels[leader.label];
    const glm::vec4 anchorClip = clipFromWorld * glm::vec4(l.anchor, 1.0f);
    const glm::vec2 centre = 0.5f * (leader.box.lo + leader.box.hi);
    // Where the line from the anchor to the box's centre enters the box.
    const glm::vec2 d = centre - leader.anchor;
    const glm::vec2 half = 0.5f * (leader.box.hi - leader.box.lo);
    const float t = 1.0f - std::min(half.x / std::max(std::abs(d.x), 1e-3f), half.y / std::max(std::abs(d.y), 1e-3f));
    const glm::vec2 start = leader.anchor + 0.25f * l.sizePx * glm::normalize(d),
                    end = leader.anchor + std::max(t, 0.0f) * d;
    auto unproject = [&](glm::vec2 px) {
      const glm::vec4 p =
          worldFromClip * glm::vec4(2.0f * px.x / float(v.width) - 1.0f, 1.0f - 2.0f * px.y / float(v.height),
                                    anchorClip.z / anchorClip.w, 1.0f);
      return glm::vec3(p) / p.w;
    };
    render::PolylineItem line;
    line.points = {unproject(start), unproject(end)};
    line.color = glm::vec4(glm::vec3(l.color) * 0.5f + 0.5f * glm::vec3(0.45f), 0.9f);
    line.widthPx = std::max(1.0f, 0.06f * l.sizePx);
    line.depthTested = false;
    line.view = view;
    list.polylines.push_back(line);
  }
}

}  // namespace

void keepLabelsClear(render::DrawList& list, int view, std::size_t first, bool nearestToAnchor) {
  const render::View& v = list.views[std::size_t(view)];
  const glm::mat4 clipFromWorld = v.camera.clipFromView * v.camera.viewFromWorld;
  const auto project = projectorOf(v, clipFromWorld);
  std::vector<Segment> obstacles = obstaclesOf(list, view);
  std::vector<Box> placed = textPlateBoxes(list, view, project);
  auto cost = [&](const Box& box) { return labelBoxCost(box, v, placed, obstacles); };
  std::vector<LabelLeader> leaders;
  // Last first: the pole labels before the axis names (z says what |0⟩
  // says), so where there is no room it is an axis name that goes.
  for (std::size_t i = list.labels.size(); i-- > first;) {
    render::LabelItem& l = list.labels[i];
    if (l.view != view || !l.worldAnchored) continue;
    float w = 1.0f;
    const glm::vec2 anchor = project(l.anchor, w);
    if (w <= 1e-4f) continue;
    const LabelBoxAt boxAt(l, anchor, nearestToAnchor);
    const std::optional<glm::vec2> best = clearLabelOffset(l, boxAt, nearestToAnchor, cost);
    if (!best) {
      // Nowhere clear within 6 em (a large text size beside a small view):
      // the label is left out rather than laid over a line or a label.
      l.text.clear();
      continue;
    }
    const glm::vec2 moved = *best - l.offsetPx;
    l.offsetPx = *best;
    placed.push_back(boxAt(*best));
    if (glm::length(moved) > 2.0f * l.sizePx) leaders.push_back({i, anchor, boxAt(*best)});
  }
  addLeaderLines(list, view, leaders, clipFromWorld);
}

std::vector<glm::vec2> keepBlocksClear(const render::DrawList& list, int view, std::vector<TextBlock>& blocks,
                                       std::vector<glm::vec2> origins, const Occupancy& subject) {
  const render::View& v = list.views[std::size_t(view)];
  const std::vector<Segment> obstacles = obstaclesOf(list, view);
  std::vector<Box> placed;
  auto clear = [&](const Box& box, float gap) {
    if (box.lo.x < 0.0f || box.lo.y < 0.0f || box.hi.x > float(v.width) || box.hi.y > float(v.height)) return false;
    const Box padded{box.lo - glm::vec2(gap), box.hi + glm::vec2(gap)};
    for (const Box& b : placed)
      if (padded.lo.x < b.hi.x && b.lo.x < padded.hi.x && padded.lo.y < b.hi.y && b.lo.y < padded.hi.y) return false;
    if (subject.anyIn(padded.lo, padded.hi)) return false;
    return std::none_of(obstacles.begin(), obstacles.end(), [&](const Segment& s) { return meets(padded, s); });
  };
  for (std::size_t i = 0; i < blocks.size() && i < origins.size(); ++i) {
    TextBlock& block = blocks[i];
    block.minSize = glm::vec2(0.0f);  // a still's digits stay: the plate fits its lines
    while (!block.lines.empty()) {
      const glm::vec2 size = blockSize(block);
      const float gap = 0.25f * block.lines.front().sizePx, step = 0.5f * block.lines.front().sizePx;
      // Where the layout put it, else the nearest clear place on a grid
      // half an em fine.
      const glm::vec2 wanted = origins[i];
      std::optional<glm::vec2> best;
      if (clear({origins[i], origins[i] + size}, gap)) best = origins[i];
      float bestDistance = std::numeric_limits<float>::max();
      for (float y = gap; !best && y + size.y + gap <= float(v.height); y += step)
        for (float x = gap; x + size.x + gap <= float(v.width); x += step) {
          const float d = glm::length(glm::vec2(x, y) - wanted);
          if (d < bestDistance && clear({{x, y}, glm::vec2(x, y) + size}, gap)) {
            bestDistance = d;
            origins[i] = {x, y};
          }
        }
      if (best || bestDistance < std::numeric_limits<float>::max()) {
        placed.push_back({origins[i], origins[i] + size});
        break;
      }
      // Nowhere clear: narrower, on more lines (down to a quarter of the
      // view), then its last line (a broken line whole) gives way.
      // (A caption never narrower than kLeastCaptionEm.)
      const float narrower = 0.75f * size.x;
      const float least = block.centred ? kLeastCaptionEm * block.lines.front().sizePx : 0.0f;
      if (narrower >= std::max(float(v.width) / 4.0f, least)) {
        TextBlock joined = block;
        joined.lines.clear();
        for (const TextLine& line : block.lines)
          if (line.continued && !joined.lines.empty()) joined.lines.back().text += " " + line.text;
          else joined.lines.push_back(line);
        wrapToWidth(joined, narrower, std::numeric_limits<float>::max());
        if (blockSize(joined).x < size.x) {
          block = joined;
          continue;
        }
      }
      for (bool piece = true; piece && !block.lines.empty();) {
        piece = block.lines.back().continued;
        block.lines.pop_back();
      }
    }
  }
  return origins;
}

}  // namespace rollspin::draw
