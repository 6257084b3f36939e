// The readback (readback.cpp): rows flipped once, each view's backdrop put
// behind the scene, straight alpha for transparent lists.
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

TEST_F(RendererTest, RowsComeBackTopFirst) {
  // View rectangles are given from the top: red over blue must come back
  // with red in row 0, i.e. the GL rows were flipped exactly once.
  DrawList list;
  list.width = 16;
  list.height = 8;
  list.views = {flatView(0, 0, 16, 2, {1, 0, 0}), flatView(0, 2, 16, 6, {0, 0, 1})};
  const media::Image img = renderer_->render(list);
  ASSERT_EQ(img.width, 16);
  EXPECT_EQ(img.pixel(5, 0)[0], 255);
  EXPECT_EQ(img.pixel(5, 0)[2], 0);
  EXPECT_EQ(img.pixel(5, 1)[0], 255);
  EXPECT_EQ(img.pixel(5, 2)[2], 255);
  EXPECT_EQ(img.pixel(5, 7)[2], 255);
  EXPECT_EQ(img.pixel(5, 7)[3], 255);
}

// The backdrop goes behind the scene as the image is read back: each pixel
// takes the gradient of the last view that holds it (an inset over a main
// view), sampled at the pixel's centre row and sRGB-encoded; pixels outside
// every view stay black.
TEST_F(RendererTest, BackdropsFollowTheViewsAndTheirGradients) {
  auto encode = [](float c) { return c < 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f; };
  DrawList list;
  list.width = 64;
  list.height = 48;
  View main = flatView(0, 0, 40, 40, glm::vec3(0.0f));
  main.backgroundTop = {0.9f, 0.1f, 0.1f};
  main.backgroundBottom = {0.1f, 0.1f, 0.9f};
  View inset = flatView(30, 10, 20, 20, glm::vec3(0.2f, 0.8f, 0.2f));
  list.views = {main, inset};
  const media::Image img = renderer_->render(list);
  for (int y = 0; y < list.height; ++y)
    for (int x = 0; x < list.width; ++x) {
      const std::uint8_t* p = img.pixel(x, y);
      ASSERT_EQ(p[3], 255) << x << "," << y;
      const bool inInset = x >= 30 && x < 50 && y >= 10 && y < 30, inMain = x < 40 && y < 40;
      if (!inInset && !inMain) {
        ASSERT_EQ(p[0] + p[1] + p[2], 0) << x << "," << y;  // between views: no backdrop
        continue;
      }
      const View& v = inInset ? inset : main;
      const float f = (float(y - v.y) + 0.5f) / float(v.height);
      for (int c = 0; c < 3; ++c) {
        const float top = encode(v.backgroundTop[c]), bottom = encode(v.backgroundBottom[c]);
        ASSERT_NEAR(p[c], 255.0f * (top + (bottom - top) * f), 0.51f) << x << "," << y << " channel " << c;
      }
    }
}

TEST_F(RendererTest, TransparentBackgroundHasZeroAlphaAndOpaqueSubject) {
  DrawList list;
  list.width = 48;
  list.height = 48;
  list.transparent = true;
  list.views = {cameraView(48, 48)};
  MeshItem ball;
  ball.mesh = uvSphere(32, 16);
  list.meshes.push_back(ball);
  const media::Image img = renderer_->render(list);
  EXPECT_EQ(img.pixel(0, 0)[3], 0);
  EXPECT_EQ(img.pixel(24, 24)[3], 255);
}

}  // namespace
}  // namespace rollspin::render
