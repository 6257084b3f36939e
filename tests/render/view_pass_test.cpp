// A view's steps (view_pass.cpp): samples only near edges, every kind of
// item drawn, the same list twice the same bytes.
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

// A view drawn whole draws its static meshes at one sample, and in samples
// only in the tiles near their edges: away from those tiles a frame with
// four samples is the frame with one, byte for byte; near them its edges
// are antialiased (pixels covered in part, which one sample never gives).
TEST_F(RendererTest, SamplesAreDrawnOnlyNearAMeshesEdges) {
  DrawList list;
  list.width = 320;
  list.height = 240;
  View v = cameraView(320, 240);
  v.camera.position = {0.3f, -2.0f, 7.0f};
  v.camera.viewFromWorld = glm::lookAt(v.camera.position, glm::vec3(0.2f, 0.4f, 0.0f), glm::vec3(0, 0, 1));
  v.background = false;
  list.views = {v};
  list.transparent = true;
  MeshItem board;  // its corner and two borders inside the view, its middle filling the rest
  board.mesh = parametricPatch(
      [](float a, float b, glm::vec3& p, glm::vec3& n) {
        p = {6.0f * a - 1.5f, 6.0f * b - 1.0f, 0.0f};
        n = {0, 0, 1};
      },
      3, 3, glm::vec2(6.0f));
  board.material.pattern = Pattern::Checker;
  board.material.specular = 0.0f;
  list.meshes.push_back(board);
  MeshItem post;  // a cylinder standing on it: silhouettes, a cap's crease, where two meshes meet
  post.mesh = unitCylinder(24);
  post.worldFromModel =
      glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(1.0f, 1.5f, 0.0f)), glm::vec3(0.4f, 0.4f, 1.2f));
  post.material.color = {0.2f, 0.4f, 0.8f};
  list.meshes.push_back(post);
  Renderer renderer(*context_, ShaderLibrary{});
  renderer.setRetainLayers(false);
  const media::Image four = renderer.render(list);
  const RenderStats& stats = renderer.stats();
  EXPECT_EQ(stats.wholeViewPixels, 320LL * 240);
  EXPECT_GT(stats.sampledPixels, 0);
  EXPECT_LT(stats.sampledPixels, stats.wholeViewPixels / 2);
  list.msaaSamples = 1;
  const media::Image one = renderer.render(list);
  long long differing = 0;
  int partial = 0, partialOne = 0;
  for (int y = 0; y < 240; ++y)
    for (int x = 0; x < 320; ++x) {
      differing += std::memcmp(four.pixel(x, y), one.pixel(x, y), 4) != 0 ? 1 : 0;
      partial += four.pixel(x, y)[3] > 0 && four.pixel(x, y)[3] < 255 ? 1 : 0;
      partialOne += one.pixel(x, y)[3] > 0 && one.pixel(x, y)[3] < 255 ? 1 : 0;
    }
  EXPECT_GT(partial, 200);  // the board's borders and the post's outline, antialiased
  EXPECT_EQ(partialOne, 0);
  EXPECT_GT(differing, partial);
  EXPECT_LE(differing, stats.sampledPixels);  // every other pixel as one sample draws it
}

TEST_F(RendererTest, ArrowsPolylinesAndLabelsDraw) {
  DrawList list;
  list.width = 96;
  list.height = 64;
  list.views = {cameraView(96, 64)};
  list.arrows.push_back({glm::vec3(-1, 0, 0), glm::vec3(1, 0, 0), 0.08f, glm::vec3(0, 1, 0), 0});
  PolylineItem line;
  line.points = {{-1, 1, 0}, {1, 1, 0}};
  line.color = {0, 0, 1, 1};
  line.widthPx = 3;
  list.polylines.push_back(line);
  LabelItem label;
  label.text = "ψ θ |0⟩";
  label.anchor = {4, 8, 0};
  label.sizePx = 12;
  label.color = {1, 1, 1, 1};
  list.labels.push_back(label);
  const media::Image img = renderer_->render(list);
  int green = 0, blue = 0, white = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const std::uint8_t* p = img.pixel(x, y);
      green += p[1] > 100 && p[0] < 50 ? 1 : 0;
      blue += p[2] > 200 && p[0] < 50 && p[1] < 50 ? 1 : 0;
      white += y < 16 && p[0] > 200 && p[1] > 200 && p[2] > 200 ? 1 : 0;
    }
  EXPECT_GT(green, 20);
  EXPECT_GT(blue, 20);
  EXPECT_GT(white, 5);
}

TEST_F(RendererTest, SameDrawListTwiceGivesIdenticalPixels) {
  DrawList list;
  list.width = 80;
  list.height = 60;
  View v = cameraView(80, 60);
  v.light.shadow = true;
  v.light.shadowRadius = 3.0f;
  list.views = {v};
  MeshItem ball;
  ball.mesh = uvSphere(32, 16);
  list.meshes.push_back(ball);
  const media::Image a = renderer_->render(list);
  const media::Image b = renderer_->render(list);
  EXPECT_EQ(a.rgba, b.rgba);
}

}  // namespace
}  // namespace rollspin::render
