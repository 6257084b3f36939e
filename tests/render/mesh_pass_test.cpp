// The mesh pass (mesh_pass.cpp): a matte checker's edges mixed in sRGB, an
// arrow's meshes lit per vertex as per pixel.
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

// A matte surface is lit per vertex and leaves the vertex stage in sRGB
// (mesh.vert): inside a checker's square a pixel is its colour lit, as the
// exact sRGB curve encodes it; on a square's edge it mixes the two squares'
// sRGB bytes, as a resolve of samples would, not their linear light. With
// red and blue squares of one brightness, R + B then stays that of either
// square (a linear mix would lift an even mix of 243 and 63 to 182 + 182).
TEST_F(RendererTest, AMatteCheckersEdgesMixItsSquaresInSrgb) {
  DrawList list;
  list.width = 96;
  list.height = 96;
  list.views = {cameraView(96, 96)};
  list.views[0].light.towardLight = glm::normalize(glm::vec3(0.3f, -0.2f, 1.0f));
  const Light& light = list.views[0].light;
  list.meshes.push_back(redBlueCheckerPlane(5.0f));
  // The light of a plane facing +z (mesh.vert): hemisphere fill and key.
  const float ndl = light.towardLight.z;
  const glm::vec3 lit = light.ambient * glm::vec3(1.0f, 1.0f, 1.02f) + (1.0f - light.ambient) * light.color * ndl;
  const float red = srgbLevel(0.9f * lit.r), dim = srgbLevel(0.05f * lit.b), green = srgbLevel(0.05f * lit.g);
  for (const int samples : {4, 1}) {
    list.msaaSamples = samples;
    const media::Image img = renderer_->render(list);
    int edges = 0, squares = 0;
    for (int y = 20; y < 76; ++y)
      for (int x = 20; x < 76; ++x) {  // well inside the plane
        const std::uint8_t* p = img.pixel(x, y);
        ASSERT_NEAR(p[1], green, 1.0f) << x << "," << y;
        ASSERT_NEAR(p[0] + p[2], red + dim, 2.0f) << x << "," << y << ": " << int(p[0]) << " " << int(p[2]);
        edges += std::min(p[0], p[2]) > dim + 20.0f ? 1 : 0;  // well mixed
        if (std::min(p[0], p[2]) <= dim + 1.0f) {
          ++squares;
          EXPECT_NEAR(std::max(p[0], p[2]), red, 1.0f) << x << "," << y;
        }
      }
    EXPECT_GT(edges, 100) << samples;  // not a test of squares alone
    EXPECT_GT(squares, 1000) << samples;
  }
}

// The arrows' own cylinder and cone are lit per vertex, highlight included
// (mesh.vert's VERTEX_LIT): their facets are a pixel or two wide, so the
// light interpolated across one is the light per pixel to within rounding.
// Against the same arrows lit per pixel (the shaders with the variant
// turned off), in samples at 4×: within a few levels nearly everywhere.
TEST_F(RendererTest, ArrowsLitPerVertexMatchTheirLightPerPixel) {
  const std::filesystem::path dir = test::freshTempDir("per_pixel_arrows");
  for (const auto& entry : std::filesystem::directory_iterator(test::sourceDir() / "shaders")) {
    std::string text = test::readFile(entry.path());
    const std::string variant = "#ifndef VERTEX_LIT\n#define VERTEX_LIT 0\n#endif\n";
    if (const std::size_t at = text.find(variant); at != std::string::npos)
      text.replace(at, variant.size(), "#undef VERTEX_LIT\n#define VERTEX_LIT 0\n");
    std::ofstream(dir / entry.path().filename(), std::ios::binary) << text;
  }
  Renderer perPixel(*context_, ShaderLibrary{dir});
  DrawList list;
  list.width = 240;
  list.height = 160;
  list.views = {cameraView(240, 160)};
  for (int k = 0; k < 5; ++k) {  // every way round the light, one towards the camera
    const float a = 1.3f * float(k);
    list.arrows.push_back({glm::vec3(0), glm::vec3(1.6f * std::cos(a), 1.1f * std::sin(a), k == 4 ? 1.5f : 0.3f), 0.07f,
                           glm::vec3(0.9f, 0.25f, 0.2f), 0});
  }
  const media::Image byVertex = renderer_->render(list);
  const media::Image byPixel = perPixel.render(list);
  ASSERT_NE(byVertex.rgba, byPixel.rgba);  // the variants differ, so each is in use
  long long arrowPixels = 0, difference = 0, within4 = 0;
  int worst = 0;
  for (int y = 0; y < 160; ++y)
    for (int x = 0; x < 240; ++x) {
      if (byPixel.pixel(x, y)[0] == 0 && byVertex.pixel(x, y)[0] == 0) continue;  // the black backdrop
      int d = 0;
      for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(int(byVertex.pixel(x, y)[c]) - int(byPixel.pixel(x, y)[c])));
      ++arrowPixels;
      difference += d;
      within4 += d <= 4 ? 1 : 0;
      worst = std::max(worst, d);
    }
  const std::string tally =
      fmt::format("{} arrow pixels, {} levels in all, {} within 4, worst {}", arrowPixels, difference, within4, worst);
  EXPECT_GT(arrowPixels, 2000) << tally;
  EXPECT_LT(double(difference) / double(arrowPixels), 1.5) << tally;  // mean, levels
  EXPECT_GT(double(within4) / double(arrowPixels), 0.9) << tally;
  EXPECT_LT(worst, 30) << tally;  // a highlight's peak, between two vertices
}

}  // namespace
}  // namespace rollspin::render
