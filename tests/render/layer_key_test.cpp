// The retained layer's key (render/layer_key.hpp) on plain draw lists: which
// views a frame must draw whole, and which tiles an in-place update redraws
// (a grown line's new segments, not its old ones; a changed, added or
// removed label's bounds; a translucent mesh's bounds), and when the layer
// must be built again instead (an opaque static mesh changed). No GL.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <vector>

#include "render/layer_key.hpp"
#include "two_views.hpp"

namespace rollspin::render {
namespace {

// Two views side by side (two_views.hpp), a static line in the first and a
// label in the second.
DrawList twoViews() {
  DrawList list = test::twoViewsLookingDown();
  PolylineItem line;
  line.points = {{-3.5f, -1.5f, 0}, {-3.0f, -1.5f, 0}, {-2.5f, -1.5f, 0}};
  list.polylines.push_back(line);
  LabelItem heading;
  heading.text = "heading";
  heading.view = 1;
  list.labels.push_back(heading);
  return list;
}

// Label bounds stand-in: a 40×20 box at the anchor (view pixels); mesh
// bounds: one rectangle per call, counted.
struct FakeBounds {
  int meshCalls = 0;
  ItemBounds bounds() {
    ItemBounds b;
    b.mesh = [this](const MeshItem&, const View& v, const glm::mat4&, std::vector<PixelRect>& out) {
      ++meshCalls;
      out.push_back({v.x + 200, 100, v.x + 220, 120});
    };
    b.label = [](const LabelItem& l, const View* v, const glm::mat4&) {
      const int ox = v != nullptr ? v->x : 0;
      return PixelRect{ox + int(l.anchor.x), int(l.anchor.y), ox + int(l.anchor.x) + 40, int(l.anchor.y) + 20};
    };
    return b;
  }
};

bool covers(const std::vector<PixelRect>& rects, int x, int y) {
  for (const PixelRect& r : rects)
    if (x >= r.x0 && x < r.x1 && y >= r.y0 && y < r.y1) return true;
  return false;
}

TEST(LayerKey, AGrownLineDirtiesItsNewSegmentsOnly) {
  DrawList list = twoViews();
  const StaticKey key = staticKeyOf(list);
  EXPECT_TRUE(sameStatic(key, list));
  // Two more points far to the right (world x = 2.5…3.5: pixels ≈ 260…300).
  list.polylines[0].points.push_back({2.5f, -1.5f, 0});
  list.polylines[0].points.push_back({3.5f, -1.5f, 0});
  EXPECT_FALSE(sameStatic(key, list));
  const auto fresh = freshViews(key, list);
  ASSERT_TRUE(fresh.has_value());
  EXPECT_EQ(*fresh, (std::vector<bool>{false, false}));
  FakeBounds fake;
  const auto rects = layerChanges(key, list, *fresh, fake.bounds());
  ASSERT_TRUE(rects.has_value());
  // World y = −1.5 is pixel row 140; x = 3 is column 280, x = −1 column 120
  // (the new segment from −2.5 to 2.5 crosses it), x = −3.25 column 10
  // (only the old segments reach it).
  EXPECT_TRUE(covers(*rects, 280, 140));
  EXPECT_TRUE(covers(*rects, 120, 140));
  EXPECT_FALSE(covers(*rects, 10, 140));
  EXPECT_FALSE(covers(*rects, 400, 140));  // the other view
  // Shrinking back dirties the same segments.
  const auto back = layerChanges(staticKeyOf(list), twoViews(), *fresh, fake.bounds());
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(*back, *rects);
}

TEST(LayerKey, LabelsThatChangeComeOrGoDirtyTheirOldAndNewBounds) {
  DrawList list = twoViews();
  const StaticKey key = staticKeyOf(list);
  LabelItem caption;
  caption.text = "caption";
  caption.view = -1;
  caption.anchor = {500, 10, 0};
  list.labels.insert(list.labels.begin(), caption);  // before the kept heading
  FakeBounds fake;
  auto rects = layerChanges(key, list, {false, false}, fake.bounds());
  ASSERT_TRUE(rects.has_value());
  EXPECT_TRUE(covers(*rects, 510, 15));
  EXPECT_FALSE(covers(*rects, 330, 5));  // the heading, paired and unchanged
  // The heading's text changes: its box (view 1, anchor 0, 0) is dirty.
  list.labels[1].text = "another heading";
  rects = layerChanges(key, list, {false, false}, fake.bounds());
  ASSERT_TRUE(rects.has_value());
  EXPECT_TRUE(covers(*rects, 330, 5));
  // A dynamic label is no part of the key.
  DrawList moving = twoViews();
  LabelItem live;
  live.dynamic = true;
  live.text = "s = 1";
  moving.labels.push_back(live);
  EXPECT_TRUE(sameStatic(staticKeyOf(twoViews()), moving));
}

// A live label's leading words are static: the key holds them as a label of
// their own, so new numbers keep the layer and new words update it there.
TEST(LayerKey, ALiveLabelsLeadingWordsAreStatic) {
  LabelItem live;
  live.dynamic = true;
  live.text = "s = 1.25 of 9";
  live.staticPrefixBytes = 4;
  const auto part = staticPartOf(live);
  ASSERT_TRUE(part.has_value());
  EXPECT_EQ(part->text, "s = ");
  EXPECT_FALSE(part->dynamic);
  EXPECT_EQ(part->staticPrefixBytes, 0u);
  LabelItem still = live;
  still.dynamic = false;
  EXPECT_EQ(staticPartOf(still), still);  // a static label is its own static part
  LabelItem centred = live;
  centred.align = Align::Center;  // its words move with the width of the rest
  EXPECT_FALSE(staticPartOf(centred).has_value());
  LabelItem whole = live;
  whole.staticPrefixBytes = 0;
  EXPECT_FALSE(staticPartOf(whole).has_value());
  whole.staticPrefixBytes = whole.text.size();  // nothing would be left to change
  EXPECT_FALSE(staticPartOf(whole).has_value());

  DrawList list = twoViews();
  list.labels.push_back(live);
  const StaticKey key = staticKeyOf(list);
  ASSERT_EQ(key.labels.size(), 2u);
  EXPECT_EQ(key.labels[1].text, "s = ");
  DrawList next = list;
  next.labels[1].text = "s = 1.50 of 9";
  EXPECT_TRUE(sameStatic(key, next));
  next.labels[1].text = "t = 1.50 of 9";
  EXPECT_FALSE(sameStatic(key, next));
  live.anchor = {100, 50, 0};
  next.labels[1].anchor = live.anchor;
  FakeBounds fake;
  const auto rects = layerChanges(key, next, {false, false}, fake.bounds());
  ASSERT_TRUE(rects.has_value());
  EXPECT_TRUE(covers(*rects, 110, 60));  // the words at their new place
  EXPECT_TRUE(covers(*rects, 10, 10));   // and at their old one
}

TEST(LayerKey, AnOpaqueMeshThatChangesNeedsANewLayerATranslucentOneItsBounds) {
  DrawList list = twoViews();
  MeshItem plate;
  plate.mesh = std::make_shared<MeshData>();
  plate.material.opacity = 0.5f;
  list.meshes.push_back(plate);
  const StaticKey key = staticKeyOf(list);
  list.meshes[0].worldFromModel = glm::translate(glm::mat4(1.0f), glm::vec3(0.5f, 0, 0));
  FakeBounds fake;
  const auto rects = layerChanges(key, list, {false, false}, fake.bounds());
  ASSERT_TRUE(rects.has_value());
  EXPECT_EQ(fake.meshCalls, 2);  // old and new place
  EXPECT_TRUE(covers(*rects, 210, 110));
  list.meshes[0].material.opacity = 1.0f;
  const StaticKey opaqueKey = staticKeyOf(list);
  list.meshes[0].worldFromModel = glm::mat4(1.0f);
  EXPECT_FALSE(layerChanges(opaqueKey, list, {false, false}, fake.bounds()).has_value());
}

TEST(LayerKey, AViewWhoseCameraMovedIsFreshAndItsItemsAreNotCompared) {
  DrawList list = twoViews();
  StaticKey key = staticKeyOf(list);
  list.views[0].camera.position = {1, 0, 5};
  list.views[0].camera.viewFromWorld =
      glm::lookAt(list.views[0].camera.position, glm::vec3(1, 0, 0), glm::vec3(0, 1, 0));
  list.polylines[0].points.push_back({3.0f, 1.0f, 0});  // in the moved view: not compared
  const auto fresh = freshViews(key, list);
  ASSERT_TRUE(fresh.has_value());
  EXPECT_EQ(*fresh, (std::vector<bool>{true, false}));
  FakeBounds fake;
  const auto rects = layerChanges(key, list, *fresh, fake.bounds());
  ASSERT_TRUE(rects.has_value());
  EXPECT_TRUE(rects->empty());
  // The shadow box follows the ball: not part of the key.
  DrawList shadowMoved = twoViews();
  shadowMoved.views[0].light.shadowCenter = {1, 2, 3};
  EXPECT_TRUE(sameStatic(staticKeyOf(twoViews()), shadowMoved));
  // A stale view is fresh even when its camera is the key's.
  key = staticKeyOf(twoViews());
  key.stale = {false, true};
  EXPECT_FALSE(sameStatic(key, twoViews()));
  EXPECT_EQ(*freshViews(key, twoViews()), (std::vector<bool>{false, true}));
  // Another size: the layer cannot serve the list at all.
  DrawList bigger = twoViews();
  bigger.width = 800;
  EXPECT_FALSE(freshViews(key, bigger).has_value());
}

}  // namespace
}  // namespace rollspin::render
