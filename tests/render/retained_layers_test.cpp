// The retained layers (retained_layers.cpp, glass_capture.cpp): frames over
// a layer, built, updated in place, with fresh views, replayed glass and
// reused images, are the bytes of the frames drawn whole.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "render/layer_key.hpp"
#include "render/screen_bounds.hpp"
#include "renderer_fixture.hpp"
#include "support/test_files.hpp"

namespace rollspin::render {
namespace {

// A two-view frame whose static part (a shadowed checker floor, a glass
// sphere, lines, labels) stays while a ball, its trail, an arrow and a live
// label move: frame k of a short clip. `rayCastGlass`: the glass is a
// ray-cast sphere, as the Bloch sphere's is.
DrawList clipFrame(int k, int samples = 4, bool rayCastGlass = false) {
  DrawList list;
  list.msaaSamples = samples;
  list.width = 160;
  list.height = 72;
  View ballView = cameraView(96, 72);
  ballView.camera.position = {0, -4, 3};
  ballView.camera.viewFromWorld = glm::lookAt(ballView.camera.position, glm::vec3(0), glm::vec3(0, 0, 1));
  ballView.camera.clipFromView = glm::perspective(glm::radians(45.0f), 96.0f / 72.0f, 0.1f, 20.0f);
  ballView.light.shadow = true;
  ballView.light.shadowRadius = 3.0f;
  ballView.light.shadowCenter = {0.3f * float(k) - 0.8f, 0, 0};
  ballView.light.shadowSoftness = 0.15f;
  View twin = cameraView(64, 72);
  twin.x = 96;
  list.views = {ballView, twin};
  // Meshes are shared across frames, as a SceneDrawer's are: the layer
  // compares static meshes by pointer.
  static const std::shared_ptr<MeshData> floorMesh = parametricPatch(
      [](float a, float b, glm::vec3& p, glm::vec3& n) {
        p = {4.0f * a - 2.0f, 4.0f * b - 2.0f, 0.0f};
        n = {0, 0, 1};
      },
      2, 2, glm::vec2(8.0f));
  static const std::shared_ptr<MeshData> sphere = uvSphere(32, 16);
  MeshItem floor;
  floor.mesh = floorMesh;
  floor.material.pattern = Pattern::Checker;
  floor.material.castsShadow = false;
  floor.material.receivesShadow = true;
  floor.material.specular = 0.0f;
  list.meshes.push_back(floor);
  MeshItem glass;
  glass.mesh = sphere;
  glass.material.opacity = 0.2f;
  glass.view = 1;
  glass.sphere = rayCastGlass;
  list.meshes.push_back(glass);
  MeshItem ball;
  ball.mesh = sphere;
  ball.worldFromModel =
      glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(0.3f * float(k) - 0.8f, 0, 0.4f)), glm::vec3(0.4f));
  ball.material.color = {0.8f, 0.7f, 0.1f};
  ball.dynamic = true;
  ball.sphere = true;  // ray-cast at one sample
  list.meshes.push_back(ball);
  PolylineItem path;
  path.points = {{-2, 0.5f, 0}, {2, 0.5f, 0}};
  list.polylines.push_back(path);
  PolylineItem trail;
  trail.dynamic = true;
  trail.color = {1, 0.4f, 0, 1};
  for (int j = 0; j <= k; ++j) trail.points.push_back({0.3f * float(j) - 0.8f, -0.5f, 0.0f});
  list.polylines.push_back(trail);
  list.arrows.push_back({glm::vec3(0), glm::vec3(std::cos(0.5f * float(k)), std::sin(0.5f * float(k)), 0.5f), 0.05f,
                         glm::vec3(0.8f, 0.1f, 0.1f), 1, true});
  LabelItem heading;
  heading.text = "static";
  heading.anchor = {4, 8, 0};
  heading.sizePx = 10;
  heading.color = {1.0f, 0.9f, 0.6f, 1.0f};  // seen on the black backdrop
  heading.view = 1;
  list.labels.push_back(heading);
  LabelItem live = heading;
  live.text = "s = " + std::to_string(k) + " of 9";
  live.anchor = {4, 60, 0};
  live.view = 0;
  live.dynamic = true;
  live.staticPrefixBytes = 4;  // "s = " stays in the layer
  list.labels.push_back(live);
  return list;
}

// Equal images; otherwise says how many pixels differ, and where.
::testing::AssertionResult sameBytes(const media::Image& a, const media::Image& b) {
  if (a.width != b.width || a.height != b.height) return ::testing::AssertionFailure() << "sizes differ";
  int count = 0, x0 = a.width, y0 = a.height, x1 = -1, y1 = -1;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x)
      if (std::memcmp(a.pixel(x, y), b.pixel(x, y), 4) != 0) {
        ++count;
        x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y);
      }
  if (count == 0) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << count << " pixels differ, in x " << x0 << "…" << x1 << ", y " << y0 << "…"
                                       << y1;
}

// The retained layer must not leak state between frames: frames drawn in
// order (most over the layer), out of order, and each drawn whole by a
// renderer that keeps no layer all give the same bytes.
TEST_F(RendererTest, RetainedLayerFramesMatchFramesDrawnWholeInAnyOrder) {
  constexpr int kFrames = 6;
  std::vector<media::Image> whole(kFrames);
  {
    Renderer plain(*context_, ShaderLibrary{});
    plain.setRetainLayers(false);
    for (int k = 0; k < kFrames; ++k) whole[k] = plain.render(clipFrame(k));
    EXPECT_EQ(plain.stats().retainedFrames, 0);
  }
  // The frames differ (the test would prove nothing otherwise).
  EXPECT_NE(whole[0].rgba, whole[1].rgba);
  Renderer inOrder(*context_, ShaderLibrary{});
  for (int k = 0; k < kFrames; ++k) EXPECT_TRUE(sameBytes(inOrder.render(clipFrame(k)), whole[k])) << "frame " << k;
  EXPECT_EQ(inOrder.stats().layerBuilds, 1);
  EXPECT_EQ(inOrder.stats().retainedFrames, kFrames - 1);
  EXPECT_GT(inOrder.stats().redrawnPixels, 0);
  EXPECT_LT(inOrder.stats().redrawnPixels, inOrder.stats().retainedPixels);
  Renderer shuffled(*context_, ShaderLibrary{});
  for (int k : {4, 1, 5, 0, 3, 2, 4, 4, 1})
    EXPECT_TRUE(sameBytes(shuffled.render(clipFrame(k)), whole[k])) << "frame " << k;
  EXPECT_GT(shuffled.stats().retainedFrames, 5);
  // A static item that changes (here the floor's colour) makes a new layer.
  DrawList changed = clipFrame(2);
  changed.meshes[0].material.color = {0.2f, 0.5f, 0.3f};
  Renderer plain(*context_, ShaderLibrary{});
  plain.setRetainLayers(false);
  const media::Image expected = plain.render(changed);
  EXPECT_NE(expected.rgba, whole[2].rgba);
  // The frame before was drawn over a layer (the camera holds still): the
  // new layer is built at once, not after a frame drawn whole.
  const RenderStats before = shuffled.stats();
  EXPECT_EQ(shuffled.render(changed).rgba, expected.rgba);
  EXPECT_EQ(shuffled.stats().layerBuilds, before.layerBuilds + 1);
  EXPECT_EQ(shuffled.stats().retainedFrames, before.retainedFrames + 1);
  changed = clipFrame(3);
  changed.meshes[0].material.color = {0.2f, 0.5f, 0.3f};
  EXPECT_EQ(shuffled.render(changed).rgba, plain.render(changed).rgba);
}

// renderWithDepth draws its list whole with retained layers off for the
// call (Impl::RetainLayersOff): afterwards they are on again, also when the
// call throws (an empty image is bad input).
TEST_F(RendererTest, RenderWithDepthTurnsRetainedLayersBackOnAlsoWhenItThrows) {
  Renderer renderer(*context_, ShaderLibrary{});
  media::Image image;
  std::vector<float> depth;
  renderer.renderWithDepth(clipFrame(0), image, depth);
  DrawList empty = clipFrame(0);
  empty.width = 0;
  EXPECT_THROW(renderer.renderWithDepth(empty, image, depth), Error);
  EXPECT_EQ(renderer.stats().layerBuilds, 0);
  for (int k = 0; k < 3; ++k) (void)renderer.render(clipFrame(k));
  EXPECT_EQ(renderer.stats().layerBuilds, 1);
  EXPECT_EQ(renderer.stats().retainedFrames, 2);
}

// The same at one sample, where the ball is ray-cast and lines take their
// coverage as alpha: both depend on a pixel's position only.
TEST_F(RendererTest, RetainedLayerFramesMatchFramesDrawnWholeAtOneSample) {
  constexpr int kFrames = 6;
  std::vector<media::Image> whole(kFrames);
  Renderer plain(*context_, ShaderLibrary{});
  plain.setRetainLayers(false);
  for (int k = 0; k < kFrames; ++k) whole[k] = plain.render(clipFrame(k, 1));
  EXPECT_NE(whole[0].rgba, whole[1].rgba);
  Renderer inOrder(*context_, ShaderLibrary{});
  for (int k = 0; k < kFrames; ++k) EXPECT_TRUE(sameBytes(inOrder.render(clipFrame(k, 1)), whole[k])) << "frame " << k;
  EXPECT_EQ(inOrder.stats().retainedFrames, kFrames - 1);
  Renderer shuffled(*context_, ShaderLibrary{});
  for (int k : {4, 1, 5, 0, 3, 2, 4, 4, 1})
    EXPECT_TRUE(sameBytes(shuffled.render(clipFrame(k, 1)), whole[k])) << "frame " << k;
  EXPECT_GT(shuffled.stats().retainedFrames, 5);
}

// The Bloch sphere's glass is a translucent ray-cast sphere. Over a layer
// it is captured once and replayed in each frame's rectangles; that gives
// the bytes of frames that cast it, in any order, where an arrow pokes out
// through its front (the depth test sees the replayed depth), and after
// its colour changes while the camera holds (captured again).
TEST_F(RendererTest, ARayCastGlassReplayedOverTheLayerMatchesFramesDrawnWhole) {
  constexpr int kFrames = 6;
  auto frame = [](int k) {
    DrawList list = clipFrame(k, 4, true);
    // Through the glass's front, towards the camera, turning.
    list.arrows.push_back({glm::vec3(0),
                           glm::vec3(0.4f * std::cos(0.7f * float(k)), 0.4f * std::sin(0.7f * float(k)), 1.3f), 0.06f,
                           glm::vec3(0.1f, 0.7f, 0.2f), 1, true});
    return list;
  };
  Renderer plain(*context_, ShaderLibrary{});
  plain.setRetainLayers(false);
  std::vector<media::Image> whole(kFrames);
  for (int k = 0; k < kFrames; ++k) whole[k] = plain.render(frame(k));
  EXPECT_EQ(plain.stats().sphereCaptures, 0);
  EXPECT_NE(whole[0].rgba, whole[1].rgba);

  Renderer inOrder(*context_, ShaderLibrary{});
  for (int k = 0; k < kFrames; ++k) EXPECT_TRUE(sameBytes(inOrder.render(frame(k)), whole[k])) << "frame " << k;
  EXPECT_EQ(inOrder.stats().retainedFrames, kFrames - 1);
  EXPECT_EQ(inOrder.stats().sphereCaptures, 1);
  EXPECT_GE(inOrder.stats().sphereReplays, kFrames - 1);

  Renderer shuffled(*context_, ShaderLibrary{});
  for (int k : {4, 1, 5, 0, 3, 2, 4, 4, 1})
    EXPECT_TRUE(sameBytes(shuffled.render(frame(k)), whole[k])) << "frame " << k;
  EXPECT_EQ(shuffled.stats().sphereCaptures, 1);

  // The glass tinted: a static translucent mesh that changed (the layer is
  // updated in place); the old capture no longer serves.
  const RenderStats before = shuffled.stats();
  DrawList tinted = frame(3);
  tinted.meshes[1].material.color = {0.9f, 0.6f, 0.3f};
  const media::Image expected = plain.render(tinted);
  EXPECT_NE(expected.rgba, whole[3].rgba);
  EXPECT_TRUE(sameBytes(shuffled.render(tinted), expected));
  EXPECT_EQ(shuffled.stats().retainedFrames, before.retainedFrames + 1);
  EXPECT_EQ(shuffled.stats().sphereCaptures, before.sphereCaptures + 1);
  tinted = frame(5);
  tinted.meshes[1].material.color = {0.9f, 0.6f, 0.3f};
  EXPECT_TRUE(sameBytes(shuffled.render(tinted), plain.render(tinted)));
}

// A ray-cast ball that passes behind the edge of a static opaque sphere (a
// mesh, resolved from its samples: against the empty backdrop its edge
// pixels are covered in part) shows through the uncovered part of those
// pixels, over a retained layer as in a frame drawn whole (SpherePass::draw's
// under pass, limited over a layer to the layer's edge tiles).
TEST_F(RendererTest, ARayCastBallBehindAStaticEdgeMatchesFramesDrawnWhole) {
  static const std::shared_ptr<MeshData> occluderMesh = uvSphere(48, 24);
  auto frame = [](int k, bool occluded) {
    DrawList list = clipFrame(k);
    list.meshes.erase(list.meshes.begin());  // no floor: the backdrop behind the occluder's edge
    if (occluded) {
      MeshItem occluder;
      occluder.mesh = occluderMesh;
      occluder.worldFromModel =
          glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(-0.1f, -1.2f, 1.15f)), glm::vec3(0.3f));
      occluder.material.color = {0.2f, 0.3f, 0.8f};
      list.meshes.insert(list.meshes.begin(), occluder);
    }
    return list;
  };
  constexpr int kFrames = 6;
  std::vector<media::Image> whole(kFrames);
  Renderer plain(*context_, ShaderLibrary{});
  plain.setRetainLayers(false);
  for (int k = 0; k < kFrames; ++k) whole[k] = plain.render(frame(k, true));
  // The occluder is in front of the ball in some frame: the under pass has
  // edge pixels to fill (frames differ where the ball is behind).
  int behind = 0;
  for (int k = 0; k < kFrames; ++k) {
    const media::Image without = plain.render(frame(k, false));
    const media::Image occluderAlone = plain.render([&] {
      DrawList l = frame(k, true);
      l.meshes.erase(l.meshes.begin() + 2);  // the ball (after the occluder and the glass)
      return l;
    }());
    for (int y = 0; y < 72; ++y)
      for (int x = 0; x < 96; ++x)
        if (std::memcmp(whole[k].pixel(x, y), without.pixel(x, y), 4) != 0 &&
            std::memcmp(whole[k].pixel(x, y), occluderAlone.pixel(x, y), 4) != 0)
          ++behind;  // neither the ball alone nor the occluder alone: both in one pixel
  }
  EXPECT_GT(behind, 10);
  Renderer inOrder(*context_, ShaderLibrary{});
  for (int k = 0; k < kFrames; ++k) EXPECT_TRUE(sameBytes(inOrder.render(frame(k, true)), whole[k])) << "frame " << k;
  EXPECT_EQ(inOrder.stats().retainedFrames, kFrames - 1);
  Renderer shuffled(*context_, ShaderLibrary{});
  for (int k : {3, 0, 5, 1, 4, 2}) EXPECT_TRUE(sameBytes(shuffled.render(frame(k, true)), whole[k])) << "frame " << k;
}

// Over the layer, a mesh or a line draws only its runs that reach the
// dirty rectangles: a small dot moving in front of a big glass sphere and a
// long static line draws few of their triangles and segments, and the frames
// are still byte for byte the frames drawn whole.
TEST_F(RendererTest, OverTheLayerOnlyPartsReachingTheRectanglesAreDrawn) {
  auto frame = [](int k) {
    DrawList list;
    list.width = list.height = 256;
    list.views = {cameraView(256, 256)};
    static const std::shared_ptr<MeshData> sphere = uvSphere(64, 32);
    MeshItem glass;
    glass.mesh = sphere;
    glass.worldFromModel = glm::scale(glm::mat4(1.0f), glm::vec3(1.6f));
    glass.material.opacity = 0.3f;
    list.meshes.push_back(glass);
    static const std::shared_ptr<MeshData> small = uvSphere(12, 6);
    MeshItem dot;
    dot.mesh = small;
    dot.worldFromModel = glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(-0.77f + 0.03f * float(k), 0.77f, 1.8f)),
                                    glm::vec3(0.08f));
    dot.material.color = {0.9f, 0.2f, 0.1f};
    dot.dynamic = true;
    list.meshes.push_back(dot);
    PolylineItem ring;  // a static circle of 256 segments round the glass, behind the dot
    for (int j = 0; j <= 256; ++j) {
      const float a = 6.2831853f * float(j) / 256.0f;
      ring.points.push_back({1.7f * std::cos(a), 1.7f * std::sin(a), 0.0f});
    }
    ring.color = {0.6f, 0.8f, 1.0f, 1.0f};
    list.polylines.push_back(ring);
    return list;
  };
  Renderer plain(*context_, ShaderLibrary{});
  plain.setRetainLayers(false);
  Renderer layered(*context_, ShaderLibrary{});
  for (int k = 0; k < 4; ++k) EXPECT_TRUE(sameBytes(layered.render(frame(k)), plain.render(frame(k)))) << "frame " << k;
  const RenderStats& st = layered.stats();
  EXPECT_EQ(st.retainedFrames, 3);
  EXPECT_GT(st.meshIndicesDrawn, 0);
  EXPECT_LT(st.meshIndicesDrawn, st.meshIndicesInRects / 2);
  EXPECT_GT(st.lineSegmentsDrawn, 0);
  EXPECT_LT(st.lineSegmentsDrawn, st.lineSegmentsInRects / 2);
}

// A growing line settles at checkpoints and a caption changes now and then
// (as a SceneDrawer's do): the static lines and labels change while the
// views and meshes hold, and the layer is brought up to date in place
// rather than built again. Frames in order, out of order (the static prefix
// then shrinks as well as grows) and drawn whole must agree byte for byte.
DrawList checkpointFrame(int k) {
  DrawList list = clipFrame(k);
  // Twice clipFrame's size (the same aspect), so that the dirty tiles tell
  // the changed items from the moving ones.
  list.width *= 2;
  list.height *= 2;
  for (View& v : list.views) v.x *= 2, v.width *= 2, v.height *= 2;
  // A line's static prefix, settling every second frame: points 0…2 at the
  // floor's far left, 3 and on at its far right, so that the one segment
  // from point 2 to point 3 alone crosses the top of the view (a tile no
  // other item dirties).
  PolylineItem settled;
  settled.color = {0.2f, 0.3f, 0.9f, 1.0f};
  settled.widthPx = 3.0f;
  for (int j = 0; j <= k - k % 2; ++j)
    settled.points.push_back(j < 3 ? glm::vec3(-1.6f + 0.1f * float(j), 1.6f, 0.0f)
                                   : glm::vec3(1.3f + 0.1f * float(j - 3), 1.5f, 0.0f));
  list.polylines.push_back(settled);
  // From frame 3 a second static line comes first (the kept lines shift),
  // a translucent plate grows, and the caption changes; from frame 5 a
  // label comes before it.
  if (k >= 3) {
    PolylineItem first;
    first.color = {0.1f, 0.6f, 0.2f, 1.0f};
    first.points = {{-1.3f, -1.4f, 0.0f}, {-0.8f, -1.4f, 0.0f}};
    list.polylines.insert(list.polylines.begin(), first);
  }
  MeshItem plate;
  plate.mesh = clipFrame(0).meshes[1].mesh;
  plate.worldFromModel =
      glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(1.6f, 1.8f, 0.3f)), glm::vec3(k < 3 ? 0.2f : 0.3f));
  plate.material.opacity = 0.5f;
  plate.material.castsShadow = false;  // the shadow box hugs the ball alone
  list.meshes.insert(list.meshes.begin() + 1, plate);
  if (k >= 5) {
    LabelItem note;
    note.text = "note";
    note.anchor = {150, 128, 0};
    note.sizePx = 10;
    note.color = {1.0f, 1.0f, 1.0f, 1.0f};
    note.view = 0;
    list.labels.push_back(note);
  }
  LabelItem caption;
  caption.text = k < 3 ? "first caption" : "second";
  caption.anchor = {60, 12, 0};
  caption.sizePx = 10;
  caption.color = {1.0f, 1.0f, 1.0f, 1.0f};
  caption.view = -1;
  list.labels.push_back(caption);
  return list;
}

// A live label's leading words stay in the layer and only the tiles of the
// rest are redrawn; the frames still equal frames drawn whole.
TEST_F(RendererTest, ALiveLabelsLeadingWordsStayInTheLayer) {
  auto frame = [](int k) {
    DrawList list;
    list.width = 256;
    list.height = 32;
    list.views = {cameraView(256, 32)};
    LabelItem live;
    live.text = "the running value is now = " + std::to_string(k);
    live.staticPrefixBytes = live.text.size() - std::to_string(k).size();
    live.anchor = {4, 16, 0};
    live.sizePx = 14;
    live.color = {1, 1, 1, 1};  // on black
    live.view = 0;
    live.dynamic = true;
    list.labels.push_back(live);
    return list;
  };
  Renderer plain(*context_, ShaderLibrary{});
  plain.setRetainLayers(false);
  Renderer layered(*context_, ShaderLibrary{});
  EXPECT_NE(plain.render(frame(1)).rgba, plain.render(frame(2)).rgba);  // the number shows
  for (int k : {1, 2, 3, 9, 7}) EXPECT_TRUE(sameBytes(layered.render(frame(k)), plain.render(frame(k)))) << "k = " << k;
  EXPECT_EQ(layered.stats().layerBuilds, 1);
  EXPECT_EQ(layered.stats().retainedFrames, 4);  // the first frame is drawn whole
  // The words span several tiles; each of the four frames over the layer
  // redraws the number's (two by two at most, where it straddles tile edges).
  EXPECT_LE(layered.stats().redrawnPixels, 4 * 4 * TileGrid::kTile * TileGrid::kTile);
}

TEST_F(RendererTest, RetainedLayerUpdatedInPlaceWhenStaticLinesOrLabelsChange) {
  constexpr int kFrames = 6;
  std::vector<media::Image> whole(kFrames);
  Renderer plain(*context_, ShaderLibrary{});
  plain.setRetainLayers(false);
  for (int k = 0; k < kFrames; ++k) whole[k] = plain.render(checkpointFrame(k));
  Renderer inOrder(*context_, ShaderLibrary{});
  for (int k = 0; k < kFrames; ++k)
    EXPECT_TRUE(sameBytes(inOrder.render(checkpointFrame(k)), whole[k])) << "frame " << k;
  // The static items change at frames 2, 3, 4 and 5.
  EXPECT_EQ(inOrder.stats().layerBuilds, 1);
  EXPECT_EQ(inOrder.stats().layerUpdates, 4);
  EXPECT_EQ(inOrder.stats().retainedFrames, kFrames - 1);
  Renderer shuffled(*context_, ShaderLibrary{});
  // The layer is built at the second 4; every later frame changes its
  // static items and is drawn over the layer brought up to date.
  for (int k : {4, 4, 1, 5, 0, 3, 2, 4, 1, 5})
    EXPECT_TRUE(sameBytes(shuffled.render(checkpointFrame(k)), whole[k])) << "frame " << k;
  EXPECT_EQ(shuffled.stats().layerBuilds, 1);
  EXPECT_EQ(shuffled.stats().layerUpdates, 8);
  EXPECT_EQ(shuffled.stats().retainedFrames, 9);
  // An opaque static mesh that changes (in the snapshot) makes a new layer.
  DrawList changed = checkpointFrame(2);
  changed.meshes[0].material.color = {0.2f, 0.5f, 0.3f};
  const RenderStats before = shuffled.stats();
  EXPECT_TRUE(sameBytes(shuffled.render(changed), plain.render(changed)));
  EXPECT_EQ(shuffled.stats().layerBuilds, before.layerBuilds + 1);
  EXPECT_EQ(shuffled.stats().layerUpdates, before.layerUpdates);
}

// A camera that follows the ball beside a twin whose camera holds: the
// ball's view is "fresh" (drawn whole inside a frame over the layer), the
// twin's view uses the layer, and its static line that grows (with the
// caption that changes) brings the layer up to date meanwhile.
DrawList followFrame(int k) {
  DrawList list = checkpointFrame(k);
  View& ball = list.views[0];
  ball.camera.position = {0.25f * float(k), -4.0f, 3.0f};
  ball.camera.viewFromWorld = glm::lookAt(ball.camera.position, glm::vec3(0.25f * float(k), 0, 0), glm::vec3(0, 0, 1));
  PolylineItem twinTrail;  // settles every second frame, as the Bloch trail does at its checkpoints
  twinTrail.view = 1;
  twinTrail.color = {0.9f, 0.2f, 0.2f, 1.0f};
  twinTrail.depthTested = false;
  for (int j = 0; j <= k - k % 2; ++j) twinTrail.points.push_back({0.4f * float(j) - 1.0f, 0.3f * float(j % 2), 0.0f});
  list.polylines.push_back(twinTrail);
  return list;
}

TEST_F(RendererTest, AViewWhoseCameraMovesIsDrawnWholeBesideALayer) {
  constexpr int kFrames = 6;
  std::vector<media::Image> whole(kFrames);
  Renderer plain(*context_, ShaderLibrary{});
  plain.setRetainLayers(false);
  for (int k = 0; k < kFrames; ++k) whole[k] = plain.render(followFrame(k));
  Renderer inOrder(*context_, ShaderLibrary{});
  for (int k = 0; k < kFrames; ++k) EXPECT_TRUE(sameBytes(inOrder.render(followFrame(k)), whole[k])) << "frame " << k;
  // Frame 0 whole; frame 1 builds the layer (the twin held); frames 2…5
  // draw the ball's view whole over it, updating it at 2, 3 and 4 (at 5
  // only the ball's view gained a label).
  EXPECT_EQ(inOrder.stats().wholeFrames, 1);
  EXPECT_EQ(inOrder.stats().layerBuilds, 1);
  EXPECT_EQ(inOrder.stats().layerUpdates, 3);
  EXPECT_EQ(inOrder.stats().freshViews, kFrames - 2);
  Renderer shuffled(*context_, ShaderLibrary{});
  for (int k : {4, 4, 1, 5, 0, 3, 2, 4, 1, 5})
    EXPECT_TRUE(sameBytes(shuffled.render(followFrame(k)), whole[k])) << "frame " << k;
  EXPECT_EQ(shuffled.stats().layerBuilds, 1);
  EXPECT_EQ(shuffled.stats().freshViews, 8);
  // The same frame again (the key now names its camera, but the layer holds
  // the ball's view as frame 4 drew it: stale), and the layer's own frame.
  EXPECT_TRUE(sameBytes(shuffled.render(followFrame(5)), whole[5]));
  EXPECT_TRUE(sameBytes(shuffled.render(followFrame(4)), whole[4]));
}

// Images reused with their histories (as a video's pool keeps them): a
// frame over the layer puts back only what differs from the layer image,
// across layer updates, fresh views, new layers and frames drawn whole in
// between; every frame must still equal the frame drawn whole.
TEST_F(RendererTest, ImagesReusedWithTheirHistoriesMatchFramesDrawnWhole) {
  constexpr int kFrames = 6;
  for (DrawList (*frame)(int) : {checkpointFrame, followFrame}) {
    std::vector<media::Image> whole(kFrames);
    Renderer plain(*context_, ShaderLibrary{});
    plain.setRetainLayers(false);
    for (int k = 0; k < kFrames; ++k) whole[k] = plain.render(frame(k));
    Renderer layered(*context_, ShaderLibrary{});
    std::array<media::Image, 3> pool;
    std::array<ImageHistory, 3> histories;
    int turn = 0;
    const std::vector<int> order{0, 1, 2, 3, 3, 4, 5, 4, 1, 5, 0, 3, 2, 4, 1, 5, 5, 2};
    for (const int k : order) {
      const int slot = turn++ % 3;
      layered.render(frame(k), pool[slot], histories[slot]);
      ASSERT_TRUE(sameBytes(pool[slot], whole[k])) << "frame " << k << ", turn " << turn;
    }
    EXPECT_GT(layered.stats().retainedFrames, 10);
    EXPECT_GT(layered.stats().layerUpdates, 3);
    // A new layer (an opaque static mesh changed), then back.
    DrawList changed = frame(2);
    changed.meshes[0].material.color = {0.2f, 0.5f, 0.3f};
    const media::Image expected = plain.render(changed);
    for (const int k : {2, 3, -1, -1, 4, 2, 2, 2}) {
      const int slot = turn++ % 3;
      layered.render(k < 0 ? changed : frame(k), pool[slot], histories[slot]);
      ASSERT_TRUE(sameBytes(pool[slot], k < 0 ? expected : whole[k])) << "frame " << k << ", turn " << turn;
    }
    // A frame drawn whole (overlapping views keep no layer) into an image
    // whose history knew the layer, then the layer's frames again.
    DrawList overlapping = frame(3);
    overlapping.views[1].x -= 8;
    const media::Image overlapped = plain.render(overlapping);
    for (int slot = 0; slot < 3; ++slot) {
      layered.render(overlapping, pool[slot], histories[slot]);
      ASSERT_TRUE(sameBytes(pool[slot], overlapped)) << "slot " << slot;
    }
    for (const int k : {2, 4, 3}) {
      const int slot = turn++ % 3;
      layered.render(frame(k), pool[slot], histories[slot]);
      ASSERT_TRUE(sameBytes(pool[slot], whole[k])) << "frame " << k << " after a whole frame, turn " << turn;
    }
    // Pixels written by someone else, the history reset: right again.
    std::fill(pool[0].rgba.begin(), pool[0].rgba.end(), std::uint8_t{77});
    histories[0].reset();
    layered.render(frame(2), pool[0], histories[0]);
    EXPECT_TRUE(sameBytes(pool[0], whole[2]));
  }
}

}  // namespace
}  // namespace rollspin::render
