// Ray-cast spheres (sphere_pass.cpp): lit, antialiased by coverage, centred,
// and the same as the multisampled mesh they replace.
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

TEST_F(RendererTest, SphereIsLitAntialiasedAndCentred) {
  DrawList list;
  list.width = 64;
  list.height = 64;
  list.views = {cameraView(64, 64)};
  MeshItem ball;
  ball.mesh = uvSphere(48, 24);
  ball.material.color = {0.8f, 0.1f, 0.1f};
  list.meshes.push_back(ball);
  list.meshes[0].material.specular = 0.0f;
  const media::Image img = renderer_->render(list);
  const std::uint8_t* centre = img.pixel(32, 32);
  EXPECT_GT(centre[0], 100);  // red and lit
  EXPECT_LT(centre[1], centre[0] / 2);
  EXPECT_EQ(img.pixel(0, 0)[0], 0);  // background (black here)

  // Multisampling: an unlit full-red disc on black has only 0 and 255
  // without it; 4× MSAA leaves intermediate coverage along the silhouette.
  list.meshes[0].material.lit = false;
  list.meshes[0].material.color = {1, 0, 0};
  const media::Image flat = renderer_->render(list);
  int partial = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      const int r = flat.pixel(x, y)[0];
      partial += r > 0 && r < 255 ? 1 : 0;
    }
  EXPECT_GT(partial, 20);
  list.msaaSamples = 1;
  const media::Image aliased = renderer_->render(list);
  EXPECT_EQ(aliased.pixel(32, 32)[0], 255);  // the disc is there, not just a blank image
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      const int r = aliased.pixel(x, y)[0];
      ASSERT_TRUE(r == 0 || r == 255) << x << "," << y << ": " << r;
    }
}

// At one sample a sphere marked `sphere` is ray-cast: its silhouette is
// antialiased by coverage (the mesh drawn at one sample has only 0 and 255),
// it covers what 4× MSAA of a fine mesh covers, and its shading matches.
TEST_F(RendererTest, RayCastSphereAtOneSampleMatchesTheMultisampledMesh) {
  DrawList list;
  list.width = 96;
  list.height = 96;
  list.views = {cameraView(96, 96)};
  MeshItem ball;
  ball.mesh = uvSphere(96, 48);
  ball.worldFromModel = glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(0.2f, -0.1f, 0.3f)), 0.7f,
                                    glm::normalize(glm::vec3(1, 2, 0))) *
                        glm::scale(glm::mat4(1.0f), glm::vec3(1.1f));
  ball.material.color = {0.8f, 0.3f, 0.1f};
  ball.material.specular = 0.3f;
  ball.sphere = true;
  list.meshes.push_back(ball);
  const media::Image multisampled = renderer_->render(list);
  list.msaaSamples = 1;
  const media::Image rayCast = renderer_->render(list);
  ASSERT_NE(rayCast.rgba, multisampled.rgba);  // not the mesh's path
  long long coveredMesh = 0, coveredCast = 0, difference = 0;
  int partial = 0, worst = 0;
  for (int y = 0; y < 96; ++y)
    for (int x = 0; x < 96; ++x) {
      const int a = multisampled.pixel(x, y)[0], b = rayCast.pixel(x, y)[0];
      coveredMesh += a;
      coveredCast += b;
      difference += std::abs(a - b);
      worst = std::max(worst, std::abs(a - b));
      partial += b > 0 && b < 100 ? 1 : 0;  // the lit interior is brighter than 100
    }
  EXPECT_GT(partial, 40);  // a ramp along the whole silhouette
  EXPECT_NEAR(double(coveredCast), double(coveredMesh), 0.01 * double(coveredMesh));
  EXPECT_LT(double(difference) / (96.0 * 96.0), 1.0);  // mean absolute difference, levels
  EXPECT_LT(worst, 80);                                // an edge pixel: 4 samples quantize coverage to quarters
  // Not ray-cast where the samples antialias, or when not marked.
  list.meshes[0].sphere = false;
  const media::Image aliased = renderer_->render(list);
  for (int y = 0; y < 96; ++y)
    for (int x = 0; x < 96; ++x) {
      const int r = aliased.pixel(x, y)[0];
      ASSERT_TRUE(r == 0 || r > 100) << x << "," << y << ": " << r;
    }
}

}  // namespace
}  // namespace rollspin::render
