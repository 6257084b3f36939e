// The retained layer's plan (render/layer_plan.hpp) over a run of plain draw
// lists: the first frame is drawn whole and remembered, a second that
// shares its static items builds the layer, later ones are drawn over it; a
// moved camera in one of two views makes that view fresh beside the layer,
// a grown static line updates it in place, overlapping views or retain off
// draw whole. No GL.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <vector>

#include "render/layer_plan.hpp"
#include "two_views.hpp"

namespace rollspin::render {
namespace {

// Two views side by side (two_views.hpp) and one short static line.
DrawList twoViews() {
  DrawList list = test::twoViewsLookingDown();
  PolylineItem line;
  line.points = {{-3.5f, -1.5f, 0}, {-3.0f, -1.5f, 0}};
  list.polylines.push_back(line);
  return list;
}

// Bounds stand-ins: the plan asks only when the layer's static items changed.
ItemBounds fakeBounds() {
  ItemBounds b;
  b.mesh = [](const MeshItem&, const View& v, const glm::mat4&, std::vector<PixelRect>& out) {
    out.push_back({v.x + 200, 100, v.x + 220, 120});
  };
  b.label = [](const LabelItem&, const View* v, const glm::mat4&) {
    const int ox = v != nullptr ? v->x : 0;
    return PixelRect{ox, 0, ox + 40, 20};
  };
  return b;
}

// Plans `list` and remembers it, as the renderer does for each frame.
LayerPlan step(LayerMemory& memory, const DrawList& list, bool retain = true) {
  LayerPlan plan = planLayer(memory, list, retain, fakeBounds());
  remember(memory, plan, list);
  return plan;
}

TEST(LayerPlan, ALayerIsBuiltWhenASecondFrameSharesTheStaticItems) {
  LayerMemory memory;
  const DrawList list = twoViews();
  const LayerPlan first = step(memory, list);
  EXPECT_EQ(first.step, LayerStep::DrawWhole);
  EXPECT_TRUE(first.rememberPending);
  EXPECT_TRUE(memory.pendingKey.has_value());
  EXPECT_FALSE(memory.layerKey.has_value());
  const LayerPlan second = step(memory, list);
  EXPECT_EQ(second.step, LayerStep::NewLayer);
  EXPECT_EQ(second.fresh, std::vector<bool>(2, false));
  EXPECT_TRUE(memory.layerKey.has_value());
  EXPECT_FALSE(memory.pendingKey.has_value());
  EXPECT_TRUE(memory.lastFrameOverLayer);
  EXPECT_EQ(step(memory, list).step, LayerStep::SameLayer);
  EXPECT_EQ(step(memory, list).step, LayerStep::SameLayer);
}

TEST(LayerPlan, RetainOffOrOverlappingViewsAlwaysDrawWhole) {
  LayerMemory memory;
  const DrawList list = twoViews();
  for (int k = 0; k < 3; ++k) {
    const LayerPlan plan = step(memory, list, false);
    EXPECT_EQ(plan.step, LayerStep::DrawWhole);
    EXPECT_FALSE(plan.rememberPending);
  }
  EXPECT_FALSE(memory.pendingKey.has_value());
  DrawList inset = twoViews();
  inset.views[1].x = 300;  // overlaps the first view
  EXPECT_FALSE(viewsDisjoint(inset));
  EXPECT_TRUE(viewsOverlap(inset.views[0], inset.views[1]));
  EXPECT_FALSE(viewsOverlap(list.views[0], list.views[1]));  // they only touch
  EXPECT_TRUE(viewsDisjoint(twoViews()));
  for (int k = 0; k < 3; ++k) EXPECT_EQ(step(memory, inset).step, LayerStep::DrawWhole);
}

TEST(LayerPlan, AViewWhoseCameraMovedIsFreshBesideTheLayer) {
  LayerMemory memory;
  DrawList list = twoViews();
  step(memory, list);
  ASSERT_EQ(step(memory, list).step, LayerStep::NewLayer);
  DrawList moved = list;
  moved.views[0].camera.position = {1, 0, 5};
  moved.views[0].camera.viewFromWorld =
      glm::lookAt(moved.views[0].camera.position, glm::vec3(1, 0, 0), glm::vec3(0, 1, 0));
  const LayerPlan plan = step(memory, moved);
  EXPECT_EQ(plan.step, LayerStep::ServedLayer);
  EXPECT_EQ(plan.fresh, (std::vector<bool>{true, false}));
  EXPECT_TRUE(plan.changes.empty());
  // The kept key marks the view stale: it stays fresh in the next frame.
  ASSERT_TRUE(memory.layerKey.has_value());
  EXPECT_EQ(memory.layerKey->stale, (std::vector<bool>{true, false}));
  // Both cameras moved: no view holds and the layer cannot serve; the
  // frame before was over it, so a layer is built at once from this one.
  DrawList bothMoved = moved;
  bothMoved.views[1].camera = moved.views[0].camera;
  EXPECT_EQ(step(memory, bothMoved).step, LayerStep::NewLayer);
  EXPECT_EQ(memory.layerKey->stale, std::vector<bool>(2, false));
}

TEST(LayerPlan, AGrownStaticLineUpdatesTheLayerInPlace) {
  LayerMemory memory;
  DrawList list = twoViews();
  step(memory, list);
  ASSERT_EQ(step(memory, list).step, LayerStep::NewLayer);
  DrawList grown = list;
  grown.polylines[0].points.push_back({-2.5f, -1.5f, 0});
  const LayerPlan plan = step(memory, grown);
  EXPECT_EQ(plan.step, LayerStep::ServedLayer);
  EXPECT_EQ(plan.fresh, std::vector<bool>(2, false));
  EXPECT_FALSE(plan.changes.empty());  // the new segment's tiles
  EXPECT_EQ(step(memory, grown).step, LayerStep::SameLayer);
}

TEST(LayerPlan, AfterAFrameOverTheLayerAChangedOpaqueMeshBuildsAnewAtOnce) {
  LayerMemory memory;
  DrawList list = twoViews();
  step(memory, list);
  ASSERT_EQ(step(memory, list).step, LayerStep::NewLayer);
  DrawList other = list;
  MeshItem plate;
  plate.mesh = std::make_shared<MeshData>();
  other.meshes.push_back(plate);  // a new static opaque mesh: the layer cannot be updated
  EXPECT_EQ(step(memory, other).step, LayerStep::NewLayer);
  // Drawn whole once, the next frame that differs again is only remembered.
  DrawList third = other;
  third.meshes[0].mesh = std::make_shared<MeshData>();
  memory.lastFrameOverLayer = false;
  memory.layerKey.reset();
  const LayerPlan plan = step(memory, third);
  EXPECT_EQ(plan.step, LayerStep::DrawWhole);
  EXPECT_TRUE(plan.rememberPending);
}

}  // namespace
}  // namespace rollspin::render
