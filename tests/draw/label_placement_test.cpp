// A still's labels and text blocks kept clear (draw/label_placement): each
// checked against what the header promises, in a view whose camera is the
// identity (world x, y in [-1, 1] map straight onto the view's pixels), so
// that every obstacle's place and width in pixels is known by hand: a label
// ends clear of the paths, arrows, plates, other labels and the view's
// edges, as near its own place as the rings allow; one moved far gets a
// leader, one with no room is left out; a block moves, breaks onto more
// lines, gives up its last lines (a broken line whole) or is not drawn.
#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "draw/clip_layout.hpp"
#include "draw/label_placement.hpp"
#include "render/draw_list.hpp"

namespace rollspin::draw::label_placement_tests {
namespace {

struct PxBox {
  glm::vec2 lo, hi;
};

// One view of w × h pixels at the image's corner, identity camera: clip =
// world, w = 1, and the focal length in pixels is h / 2.
render::DrawList identityViewList(int w, int h) {
  render::DrawList list;
  list.width = w;
  list.height = h;
  render::View v;
  v.width = w;
  v.height = h;
  list.views.push_back(v);
  return list;
}

// The world point (z = 0) that the identity camera shows at pixel px (y down).
glm::vec3 worldAtPx(const render::DrawList& list, glm::vec2 px, int view = 0) {
  const render::View& v = list.views[std::size_t(view)];
  return {2.0f * px.x / float(v.width) - 1.0f, 1.0f - 2.0f * px.y / float(v.height), 0.0f};
}

glm::vec2 pxOfWorld(const render::DrawList& list, glm::vec3 p, int view = 0) {
  const render::View& v = list.views[std::size_t(view)];
  return {(p.x * 0.5f + 0.5f) * float(v.width), (0.5f - p.y * 0.5f) * float(v.height)};
}

render::LabelItem worldLabel(const render::DrawList& list, const std::string& text, glm::vec2 anchorPx,
                             float sizePx = 20.0f, render::Align align = render::Align::Center) {
  render::LabelItem l;
  l.text = text;
  l.anchor = worldAtPx(list, anchorPx);
  l.worldAnchored = true;
  l.sizePx = sizePx;
  l.align = align;
  l.view = 0;
  return l;
}

// A label's text box in pixels (the text one em high, centred on the
// anchor plus offset; Left starts there, Right ends there), padded by `padEm`.
PxBox labelBoxPx(const render::DrawList& list, const render::LabelItem& l, float padEm) {
  const float w = textWidthPx(l.text, l.sizePx, l.bold);
  const glm::vec2 at = pxOfWorld(list, l.anchor, l.view) + l.offsetPx;
  const float x0 = l.align == render::Align::Left ? at.x : l.align == render::Align::Right ? at.x - w : at.x - 0.5f * w;
  const float pad = padEm * l.sizePx;
  return {{x0 - pad, at.y - 0.5f * l.sizePx - pad}, {x0 + w + pad, at.y + 0.5f * l.sizePx + pad}};
}

// The distance from a box to the segment a–b (0 where it enters the box),
// by dense sampling: independent of the code's closed-form test.
float boxSegmentDistance(const PxBox& b, glm::vec2 a, glm::vec2 c) {
  float best = 1e30f;
  for (int i = 0; i <= 4000; ++i) {
    const glm::vec2 p = a + (c - a) * (float(i) / 4000.0f);
    best = std::min(best, glm::length(p - glm::clamp(p, b.lo, b.hi)));
  }
  return best;
}

bool boxesOverlap(const PxBox& a, const PxBox& b) {
  return a.lo.x < b.hi.x && b.lo.x < a.hi.x && a.lo.y < b.hi.y && b.lo.y < a.hi.y;
}

bool boxInsideView(const PxBox& b, const render::DrawList& list, int view = 0) {
  const render::View& v = list.views[std::size_t(view)];
  return b.lo.x >= 0.0f && b.lo.y >= 0.0f && b.hi.x <= float(v.width) && b.hi.y <= float(v.height);
}

render::PolylineItem pathAcross(const render::DrawList& list, glm::vec2 fromPx, glm::vec2 toPx, float widthPx,
                                bool labelsKeepOff = true) {
  render::PolylineItem p;
  p.points = {worldAtPx(list, fromPx), worldAtPx(list, toPx)};
  p.widthPx = widthPx;
  p.labelsKeepOff = labelsKeepOff;
  p.view = 0;
  return p;
}

// ---- keepLabelsClear ------------------------------------------------------

TEST(LabelPlacement, AClearLabelKeepsItsPlace) {
  render::DrawList list = identityViewList(400, 300);
  render::LabelItem l = worldLabel(list, "x", {200.0f, 150.0f});
  l.offsetPx = {5.0f, -3.0f};
  list.labels.push_back(l);
  keepLabelsClear(list, 0, 0);
  EXPECT_EQ(list.labels[0].offsetPx, glm::vec2(5.0f, -3.0f));
  EXPECT_EQ(list.labels[0].text, "x");
  EXPECT_TRUE(list.polylines.empty()) << "a label that did not move needs no leader";
}

TEST(LabelPlacement, ALabelMovesOffAPathByNoMoreThanTheNearestRing) {
  render::DrawList list = identityViewList(400, 300);
  const glm::vec2 anchor{200.0f, 150.0f};
  // A path straight through the label's anchor, across the whole view.
  list.polylines.push_back(pathAcross(list, {0.0f, 150.0f}, {400.0f, 150.0f}, 2.0f));
  list.labels.push_back(worldLabel(list, "|0>", anchor));
  keepLabelsClear(list, 0, 0);
  const render::LabelItem& l = list.labels[0];
  ASSERT_FALSE(l.text.empty());
  // Its padded box keeps off the line by the line's half width (1 px) at least.
  const PxBox box = labelBoxPx(list, l, 0.25f);
  EXPECT_GE(boxSegmentDistance(box, {0.0f, 150.0f}, {400.0f, 150.0f}), 1.0f - 1e-3f);
  // Clear needs |dy| > half the padded height (0.75 em = 15 px) plus 1 px:
  // the half-em ring cannot, the one-em ring can (straight down is clear).
  const float moved = glm::length(l.offsetPx);
  EXPECT_GT(moved, 16.0f);
  EXPECT_LE(moved, 20.0f + 1e-3f) << "not the nearest ring with a clear place";
  EXPECT_EQ(list.polylines.size(), 1u) << "moved under 2 em: no leader line";
}

TEST(LabelPlacement, GridLinesAndOtherViewsPathsDoNotPushLabels) {
  render::DrawList list = identityViewList(400, 300);
  list.views.push_back(list.views[0]);
  // A grid line (labels may lie over it) and a path of another view.
  list.polylines.push_back(pathAcross(list, {0.0f, 150.0f}, {400.0f, 150.0f}, 2.0f, false));
  render::PolylineItem other = pathAcross(list, {0.0f, 150.0f}, {400.0f, 150.0f}, 2.0f);
  other.view = 1;
  list.polylines.push_back(other);
  list.labels.push_back(worldLabel(list, "x", {200.0f, 150.0f}));
  keepLabelsClear(list, 0, 0);
  EXPECT_EQ(list.labels[0].offsetPx, glm::vec2(0.0f));
}

TEST(LabelPlacement, ALabelKeepsOffAnArrowsShaftAndHead) {
  render::DrawList list = identityViewList(400, 400);
  // A flat arrow from pixel (40, 200) to (360, 200); world length 1.6, shaft
  // radius 0.02 world = 4 px (focal 200 px): the shaft meets what comes
  // within 5 px, the head (2.6 radii) within 11.4 px. The neck lies
  // min(0.35 × 1.6, 6 × 0.02) = 0.12 world (24 px) short of the tip.
  render::ArrowItem a;
  a.origin = worldAtPx(list, {40.0f, 200.0f});
  a.tip = worldAtPx(list, {360.0f, 200.0f});
  a.shaftRadius = 0.02f;
  list.arrows.push_back(a);
  list.labels.push_back(worldLabel(list, "x", {150.0f, 200.0f}));  // on the shaft
  list.labels.push_back(worldLabel(list, "y", {340.0f, 203.0f}));  // on the head
  keepLabelsClear(list, 0, 0);
  for (const render::LabelItem& l : list.labels) {
    ASSERT_FALSE(l.text.empty());
    const PxBox box = labelBoxPx(list, l, 0.25f);
    EXPECT_GE(boxSegmentDistance(box, {40.0f, 200.0f}, {336.0f, 200.0f}), 5.0f - 1e-2f) << l.text;
    EXPECT_GE(boxSegmentDistance(box, {336.0f, 200.0f}, {360.0f, 200.0f}), 11.4f - 1e-2f) << l.text;
  }
}

TEST(LabelPlacement, LabelsKeepOffEachOtherTheLastKeepingItsPlace) {
  render::DrawList list = identityViewList(400, 300);
  list.labels.push_back(worldLabel(list, "first", {200.0f, 150.0f}));
  list.labels.push_back(worldLabel(list, "second", {200.0f, 150.0f}));
  keepLabelsClear(list, 0, 0);
  // The last is placed first: it keeps its place, the other makes way.
  EXPECT_EQ(list.labels[1].offsetPx, glm::vec2(0.0f));
  EXPECT_NE(list.labels[0].offsetPx, glm::vec2(0.0f));
  EXPECT_FALSE(boxesOverlap(labelBoxPx(list, list.labels[0], 0.25f), labelBoxPx(list, list.labels[1], 0.25f)));
}

TEST(LabelPlacement, LabelsKeepOffTheTextPlates) {
  render::DrawList list = identityViewList(400, 300);
  // A text block's plate: a quad over pixels (150, 120)–(260, 180).
  auto quad = std::make_shared<render::MeshData>();
  for (const glm::vec2 px : {glm::vec2(150, 120), glm::vec2(260, 120), glm::vec2(150, 180), glm::vec2(260, 180)})
    quad->vertices.push_back({worldAtPx(list, px)});
  quad->indices = {0, 1, 2, 1, 3, 2};
  render::MeshItem plate;
  plate.mesh = quad;
  plate.textPlate = true;
  plate.material.opacity = 0.8f;
  list.meshes.push_back(plate);
  list.labels.push_back(worldLabel(list, "z", {200.0f, 150.0f}));
  keepLabelsClear(list, 0, 0);
  ASSERT_FALSE(list.labels[0].text.empty());
  EXPECT_FALSE(boxesOverlap(labelBoxPx(list, list.labels[0], 0.25f), PxBox{{150, 120}, {260, 180}}));
}

TEST(LabelPlacement, ALabelStaysWithinTheView) {
  render::DrawList list = identityViewList(400, 300);
  // Left-aligned at the right edge: its text would run out of the view.
  list.labels.push_back(worldLabel(list, "edge", {395.0f, 150.0f}, 20.0f, render::Align::Left));
  // Centred on the top edge: half of it above the view.
  list.labels.push_back(worldLabel(list, "top", {200.0f, 2.0f}));
  keepLabelsClear(list, 0, 0);
  for (const render::LabelItem& l : list.labels) {
    ASSERT_FALSE(l.text.empty());
    EXPECT_TRUE(boxInsideView(labelBoxPx(list, l, 0.25f), list)) << l.text;
  }
}

TEST(LabelPlacement, ALabelMovedOverTwoEmGetsALeaderFromItsAnchorToItsBox) {
  render::DrawList list = identityViewList(400, 300);
  const glm::vec2 anchor{200.0f, 150.0f};
  // A path 80 px wide through the anchor: clear needs |dy| > 15 + 41 px,
  // more than 2 em (40 px).
  list.polylines.push_back(pathAcross(list, {0.0f, 150.0f}, {400.0f, 150.0f}, 80.0f));
  list.labels.push_back(worldLabel(list, "n", anchor));
  keepLabelsClear(list, 0, 0);
  const render::LabelItem& l = list.labels[0];
  ASSERT_FALSE(l.text.empty());
  ASSERT_GT(glm::length(l.offsetPx), 40.0f);
  ASSERT_EQ(list.polylines.size(), 2u);
  const render::PolylineItem& leader = list.polylines[1];
  EXPECT_EQ(leader.view, 0);
  EXPECT_FALSE(leader.depthTested) << "a leader is drawn over everything";
  EXPECT_FALSE(leader.labelsKeepOff);
  ASSERT_EQ(leader.points.size(), 2u);
  const glm::vec2 start = pxOfWorld(list, leader.points[0]), end = pxOfWorld(list, leader.points[1]);
  // From a quarter em off the anchor, towards the box, to the box's edge.
  EXPECT_NEAR(glm::length(start - anchor), 5.0f, 0.05f);
  const PxBox box = labelBoxPx(list, l, 0.25f);
  const glm::vec2 centre = 0.5f * (box.lo + box.hi);
  EXPECT_GT(glm::dot(end - start, centre - anchor), 0.0f);
  const float toEdge = std::min(
      {std::abs(end.x - box.lo.x), std::abs(end.x - box.hi.x), std::abs(end.y - box.lo.y), std::abs(end.y - box.hi.y)});
  EXPECT_LT(toEdge, 0.05f) << "the leader stops at the box";
  EXPECT_LT(glm::length(end - glm::clamp(end, box.lo, box.hi)), 0.05f);
}

TEST(LabelPlacement, ALabelWithNoClearPlaceIsLeftOut) {
  render::DrawList list = identityViewList(120, 60);
  render::LabelItem l = worldLabel(list, "a label far wider than its view", {60.0f, 30.0f});
  ASSERT_GT(textWidthPx(l.text, l.sizePx, l.bold), 120.0f);  // no place inside the view
  list.labels.push_back(l);
  keepLabelsClear(list, 0, 0);
  EXPECT_TRUE(list.labels[0].text.empty());
  EXPECT_TRUE(list.polylines.empty());
}

TEST(LabelPlacement, OnlyTheViewsWorldAnchoredLabelsFromFirstOnMove) {
  render::DrawList list = identityViewList(400, 300);
  list.views.push_back(list.views[0]);
  list.polylines.push_back(pathAcross(list, {0.0f, 150.0f}, {400.0f, 150.0f}, 2.0f));
  list.labels.push_back(worldLabel(list, "before first", {200.0f, 150.0f}));
  render::LabelItem pixels = worldLabel(list, "in pixels", {200.0f, 150.0f});
  pixels.worldAnchored = false;
  list.labels.push_back(pixels);
  render::LabelItem otherView = worldLabel(list, "other view", {200.0f, 150.0f});
  otherView.view = 1;
  list.labels.push_back(otherView);
  list.labels.push_back(worldLabel(list, "moves", {200.0f, 150.0f}));
  keepLabelsClear(list, 0, 1);
  for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(list.labels[i].offsetPx, glm::vec2(0.0f)) << list.labels[i].text;
  EXPECT_NE(list.labels[3].offsetPx, glm::vec2(0.0f));
}

TEST(LabelPlacement, NearestToAnchorTakesTheClearPlaceWhoseBoxIsNearestTheAnchor) {
  render::DrawList list = identityViewList(400, 300);
  const glm::vec2 anchor{200.0f, 150.0f};
  render::LabelItem l = worldLabel(list, "label", anchor, 20.0f, render::Align::Left);
  const float w = textWidthPx(l.text, l.sizePx, l.bold);
  // A path down the middle of the label's text, top to bottom of the view:
  // it clears only by moving past it sideways, as far to either side, but
  // only moved to the left does its box still cover the anchor.
  const float x = anchor.x + 0.5f * w;
  list.polylines.push_back(pathAcross(list, {x, 0.0f}, {x, 300.0f}, 2.0f));
  list.labels.push_back(l);
  render::DrawList plain = list;
  keepLabelsClear(list, 0, 0, true);
  keepLabelsClear(plain, 0, 0, false);
  ASSERT_FALSE(list.labels[0].text.empty());
  ASSERT_FALSE(plain.labels[0].text.empty());
  // Close labels are padded an eighth of an em.
  const PxBox nearest = labelBoxPx(list, list.labels[0], 0.125f);
  EXPECT_GE(boxSegmentDistance(nearest, {x, 0.0f}, {x, 300.0f}), 1.0f - 1e-3f);
  EXPECT_LT(glm::length(anchor - glm::clamp(anchor, nearest.lo, nearest.hi)), 0.25f * l.sizePx);
  // Either way it is clear; the first clear place found need not be nearest.
  const PxBox first = labelBoxPx(plain, plain.labels[0], 0.25f);
  EXPECT_GE(boxSegmentDistance(first, {x, 0.0f}, {x, 300.0f}), 1.0f - 1e-3f);
}

// ---- keepBlocksClear ------------------------------------------------------

TextBlock blockOf(const std::vector<std::string>& texts, float sizePx = 20.0f) {
  TextBlock b;
  for (const std::string& t : texts) {
    TextLine line;
    line.text = t;
    line.sizePx = sizePx;
    b.lines.push_back(line);
  }
  return b;
}

PxBox blockBoxPx(const TextBlock& b, glm::vec2 origin) { return {origin, origin + blockSize(b)}; }

TEST(LabelPlacement, AClearBlockKeepsItsOrigin) {
  const render::DrawList list = identityViewList(400, 300);
  std::vector<TextBlock> blocks{blockOf({"s = 1.5", "t = 2"})};
  const Occupancy subject(400, 300);
  const std::vector<glm::vec2> origins = keepBlocksClear(list, 0, blocks, {{30.0f, 40.0f}}, subject);
  ASSERT_EQ(origins.size(), 1u);
  EXPECT_EQ(origins[0], glm::vec2(30.0f, 40.0f));
  EXPECT_EQ(blocks[0].lines.size(), 2u);
}

TEST(LabelPlacement, ABlockMovesOffTheSubjectToANearClearPlace) {
  const render::DrawList list = identityViewList(400, 300);
  std::vector<TextBlock> blocks{blockOf({"facts"})};
  Occupancy subject(400, 300);
  subject.rect({0.0f, 0.0f}, {200.0f, 300.0f});  // the ball over the left half
  const glm::vec2 from{180.0f, 100.0f};
  const std::vector<glm::vec2> origins = keepBlocksClear(list, 0, blocks, {from}, subject);
  ASSERT_EQ(blocks[0].lines.size(), 1u);
  const PxBox box = blockBoxPx(blocks[0], origins[0]);
  const float gap = 0.25f * 20.0f, step = 0.5f * 20.0f, cell = 300.0f / 160.0f;
  EXPECT_TRUE(boxInsideView(box, list));
  EXPECT_GE(box.lo.x - gap, 200.0f);
  EXPECT_FALSE(subject.anyIn(box.lo - glm::vec2(gap), box.hi + glm::vec2(gap)));
  // Just right of the marked cells, on the half-em grid: no farther than
  // the shift that clears them plus one grid step each way.
  const float needed = 200.0f + cell + gap - from.x;
  EXPECT_LE(glm::length(origins[0] - from), std::hypot(needed + step, step)) << origins[0].x << ", " << origins[0].y;
}

TEST(LabelPlacement, BlocksKeepOffEachOther) {
  const render::DrawList list = identityViewList(400, 300);
  std::vector<TextBlock> blocks{blockOf({"first block"}), blockOf({"second block"})};
  const Occupancy subject(400, 300);
  const std::vector<glm::vec2> origins = keepBlocksClear(list, 0, blocks, {{50.0f, 50.0f}, {50.0f, 50.0f}}, subject);
  EXPECT_EQ(origins[0], glm::vec2(50.0f, 50.0f)) << "the first block was clear where it was";
  PxBox second = blockBoxPx(blocks[1], origins[1]);
  second.lo -= glm::vec2(5.0f), second.hi += glm::vec2(5.0f);  // a quarter em apart
  EXPECT_FALSE(boxesOverlap(blockBoxPx(blocks[0], origins[0]), second));
  EXPECT_TRUE(boxInsideView(blockBoxPx(blocks[1], origins[1]), list));
}

TEST(LabelPlacement, ABlockKeepsOffThePathAndTheArrows) {
  render::DrawList list = identityViewList(400, 300);
  list.polylines.push_back(pathAcross(list, {0.0f, 60.0f}, {400.0f, 60.0f}, 4.0f));
  render::ArrowItem a;
  a.origin = worldAtPx(list, {300.0f, 0.0f});
  a.tip = worldAtPx(list, {300.0f, 300.0f});
  a.shaftRadius = 0.01f;  // 1.5 px (focal 150 px): the shaft meets what comes within 2.5 px
  list.arrows.push_back(a);
  std::vector<TextBlock> blocks{blockOf({"over the path"}), blockOf({"on the arrow"})};
  const Occupancy subject(400, 300);
  const std::vector<glm::vec2> origins = keepBlocksClear(list, 0, blocks, {{20.0f, 40.0f}, {280.0f, 150.0f}}, subject);
  for (std::size_t i = 0; i < 2; ++i) {
    ASSERT_FALSE(blocks[i].lines.empty());
    PxBox box = blockBoxPx(blocks[i], origins[i]);
    box.lo -= glm::vec2(5.0f), box.hi += glm::vec2(5.0f);
    EXPECT_GE(boxSegmentDistance(box, {0.0f, 60.0f}, {400.0f, 60.0f}), 3.0f - 1e-3f) << i;
    // The shaft only: the head (the last 0.06 world, 9 px) is at the bottom edge.
    EXPECT_GE(boxSegmentDistance(box, {300.0f, 0.0f}, {300.0f, 291.0f}), 2.5f - 1e-2f) << i;
  }
}

TEST(LabelPlacement, ABlockTooWideForTheViewBreaksOntoMoreLines) {
  const render::DrawList list = identityViewList(400, 300);
  const std::string text = "the ball rolls once round the circle and its twin turns half as far";
  std::vector<TextBlock> blocks{blockOf({text})};
  ASSERT_GT(blockSize(blocks[0]).x, 400.0f);
  const Occupancy subject(400, 300);
  const std::vector<glm::vec2> origins = keepBlocksClear(list, 0, blocks, {{0.0f, 0.0f}}, subject);
  ASSERT_GT(blocks[0].lines.size(), 1u);
  EXPECT_TRUE(boxInsideView(blockBoxPx(blocks[0], origins[0]), list));
  // Every word is still there, in order: the line broken, not cut.
  std::string joined;
  for (const TextLine& line : blocks[0].lines) {
    joined += (joined.empty() ? "" : " ") + line.text;
    EXPECT_EQ(line.sizePx, 20.0f) << "broken at spaces, not shrunk";
  }
  EXPECT_EQ(joined, text);
  for (std::size_t i = 1; i < blocks[0].lines.size(); ++i) EXPECT_TRUE(blocks[0].lines[i].continued);
}

TEST(LabelPlacement, ABlockWithNoRoomGivesUpItsLastLinesABrokenLineWhole) {
  // A heading over a fact broken onto two lines; the view (wide, so that
  // narrowing is not tried) is 4 em high: room for two lines (3.25 em and a
  // quarter em's gap each side), not three. The broken fact goes whole.
  TextBlock b = blockOf({"Heading", "a fact that", "was broken"});
  b.lines[2].continued = true;
  TextBlock two = b;
  two.lines.pop_back();
  ASSERT_LE(blockSize(two).y + 10.0f, 80.0f);
  ASSERT_GT(blockSize(b).y + 10.0f, 80.0f);
  const render::DrawList list = identityViewList(800, 80);
  ASSERT_LT(0.75f * blockSize(b).x, 800.0f / 4.0f);
  std::vector<TextBlock> blocks{b};
  const Occupancy subject(800, 80);
  const std::vector<glm::vec2> origins = keepBlocksClear(list, 0, blocks, {{10.0f, 5.0f}}, subject);
  ASSERT_EQ(blocks[0].lines.size(), 1u);
  EXPECT_EQ(blocks[0].lines[0].text, "Heading");
  EXPECT_TRUE(boxInsideView(blockBoxPx(blocks[0], origins[0]), list));
}

TEST(LabelPlacement, ABlockWithNoRoomAtAllIsNotDrawn) {
  const render::DrawList list = identityViewList(400, 300);
  Occupancy subject(400, 300);
  subject.rect({0.0f, 0.0f}, {400.0f, 300.0f});
  std::vector<TextBlock> blocks{blockOf({"nowhere", "to go"})};
  keepBlocksClear(list, 0, blocks, {{10.0f, 10.0f}}, subject);
  EXPECT_TRUE(blocks[0].lines.empty());
}

}  // namespace
}  // namespace rollspin::draw::label_placement_tests
