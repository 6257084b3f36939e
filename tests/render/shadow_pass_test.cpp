// Shadows (shadow_pass.cpp, the re-shade in mesh_pass.cpp): a ray-cast
// sphere's shadow, and a receiver's colours in its shadow.
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

// A sphere casts its shadow ray-cast into the shadow map (its depth per
// texel, not its triangles): on the floor, away from the ball itself, the
// shadow is the one its fine mesh casts, within a level or two along the
// filtered penumbra.
TEST_F(RendererTest, ARayCastSpheresShadowIsTheShadowOfItsTriangles) {
  DrawList list;
  list.width = 192;
  list.height = 144;
  View v = cameraView(192, 144);
  v.camera.position = {0, -3, 6};
  v.camera.viewFromWorld = glm::lookAt(v.camera.position, glm::vec3(0), glm::vec3(0, 0, 1));
  v.camera.clipFromView = glm::perspective(glm::radians(40.0f), 192.0f / 144.0f, 0.1f, 20.0f);
  v.light.shadow = true;
  v.light.towardLight = glm::normalize(glm::vec3(1.0f, 0.4f, 0.9f));
  v.light.shadowRadius = 2.0f;
  v.light.shadowSoftness = 0.08f;
  list.views = {v};
  MeshItem floor;
  floor.mesh = parametricPatch(
      [](float a, float b, glm::vec3& p, glm::vec3& n) {
        p = {6.0f * a - 3.0f, 6.0f * b - 3.0f, 0.0f};
        n = {0, 0, 1};
      },
      1, 1);
  floor.material.color = {0.8f, 0.8f, 0.8f};
  floor.material.castsShadow = false;
  floor.material.receivesShadow = true;
  floor.material.specular = 0.0f;
  list.meshes.push_back(floor);
  MeshItem ball;
  ball.mesh = uvSphere(192, 96);
  const glm::vec3 centre(0.2f, 0.1f, 0.5f);
  ball.worldFromModel = glm::scale(glm::translate(glm::mat4(1.0f), centre), glm::vec3(0.5f));
  ball.material.color = {0.2f, 0.3f, 0.8f};
  ball.sphere = true;
  list.meshes.push_back(ball);
  const media::Image rayCast = renderer_->render(list);
  list.meshes[1].sphere = false;  // its triangles, in the shadow map too
  const media::Image triangles = renderer_->render(list);
  list.meshes[1].material.castsShadow = false;
  const media::Image unshadowed = renderer_->render(list);
  const std::optional<PixelRect> ballRect = sphereBounds(v, centre, 0.5f, 3.0f);
  ASSERT_TRUE(ballRect.has_value());
  long long difference = 0, shadowedCast = 0, shadowedMesh = 0, floorPixels = 0;  // and the backdrop
  int worst = 0;
  for (int y = 0; y < 144; ++y)
    for (int x = 0; x < 192; ++x) {
      if (x >= ballRect->x0 && x < ballRect->x1 && y >= ballRect->y0 && y < ballRect->y1) continue;
      const int a = rayCast.pixel(x, y)[0], b = triangles.pixel(x, y)[0], lit = unshadowed.pixel(x, y)[0];
      ++floorPixels;
      difference += std::abs(a - b);
      worst = std::max(worst, std::abs(a - b));
      shadowedCast += a < lit - 20 ? 1 : 0;
      shadowedMesh += b < lit - 20 ? 1 : 0;
    }
  EXPECT_GT(shadowedMesh, 400);  // the shadow falls beside the ball
  EXPECT_NEAR(double(shadowedCast), double(shadowedMesh), 0.02 * double(shadowedMesh));
  EXPECT_LT(double(difference) / double(floorPixels), 0.05);  // mean absolute difference, levels
  EXPECT_LE(worst, 12);                                       // a penumbra pixel: a tap or two of sixteen
}

// In the shadow the re-shade (drawn over the shadow box, per pixel) mixes
// the squares in sRGB too: inside the umbra, where only the ambient light
// is left, R + B of every pixel is that of either square darkened, at the
// squares' edges as well (a linear mix there would be a seam at the box).
TEST_F(RendererTest, AMatteCheckersSquaresMixInSrgbInItsShadowToo) {
  DrawList list;
  list.width = 192;
  list.height = 192;
  View v = cameraView(192, 192);
  v.light.shadow = true;
  v.light.towardLight = glm::normalize(glm::vec3(1.0f, 0.0f, 1.0f));
  v.light.shadowRadius = 3.0f;
  v.light.shadowSoftness = 0.05f;
  list.views = {v};
  MeshItem floor = redBlueCheckerPlane(10.0f);
  floor.material.castsShadow = false;
  floor.material.receivesShadow = true;
  list.meshes.push_back(floor);
  // A ball up and to the light's side: its shadow falls on the plane beside it.
  MeshItem ball;
  ball.mesh = uvSphere(64, 32);
  ball.worldFromModel = glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(0.9f, 0.0f, 1.0f)), glm::vec3(0.5f));
  ball.material.color = {0.9f, 0.9f, 0.9f};
  list.meshes.push_back(ball);
  // Only the ambient fill in the umbra (mesh.vert's hemisphere, facing +z).
  const glm::vec3 ambient = v.light.ambient * glm::vec3(1.0f, 1.0f, 1.02f);
  const float red = srgbLevel(0.9f * ambient.r), dim = srgbLevel(0.05f * ambient.b),
              green = srgbLevel(0.05f * ambient.g);
  for (const int samples : {4, 1}) {
    list.msaaSamples = samples;
    const media::Image img = renderer_->render(list);
    // The umbra: green at its shadowed level here and 3 pixels around
    // (the penumbra's light lifts red and blue faster than green).
    auto dark = [&](int x, int y) { return std::abs(img.pixel(x, y)[1] - green) <= 0.5f; };
    int umbra = 0, edges = 0;
    for (int y = 3; y < 189; ++y)
      for (int x = 3; x < 100; ++x) {  // left of the ball (x < 0.1 in the world)
        bool inside = true;
        for (int dy = -3; dy <= 3 && inside; ++dy)
          for (int dx = -3; dx <= 3 && inside; ++dx) inside = dark(x + dx, y + dy);
        if (!inside) continue;
        const std::uint8_t* p = img.pixel(x, y);
        ++umbra;
        ASSERT_NEAR(p[0] + p[2], red + dim, 2.0f)
            << samples << ": " << x << "," << y << ": " << int(p[0]) << " " << int(p[2]);
        edges += std::min(p[0], p[2]) > dim + 6.0f ? 1 : 0;
      }
    EXPECT_GT(umbra, 600) << samples;  // the umbra is found
    EXPECT_GT(edges, 60) << samples;   // and squares' edges cross it
  }
}

}  // namespace
}  // namespace rollspin::render
