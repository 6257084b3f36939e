// The renderer on hand-built DrawLists: row order, MSAA resolve, transparency,
// arrows and labels, in-process determinism, shader embedding.
#include "render/renderer.hpp"

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
#include "render/gl_context.hpp"
#include "render/layer_key.hpp"
#include "render/mesh_builders.hpp"
#include "render/screen_bounds.hpp"
#include "support/cli_runner.hpp"

namespace rollspin::render {
namespace {

class RendererTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    context_ = createContext().release();  // ROLLSPIN_GL chooses the backend
    renderer_ = new Renderer(*context_, ShaderLibrary{});
  }
  static void TearDownTestSuite() {
    delete renderer_;
    delete context_;
  }
  static GlContext* context_;
  static Renderer* renderer_;
};
GlContext* RendererTest::context_ = nullptr;
Renderer* RendererTest::renderer_ = nullptr;

View flatView(int x, int y, int w, int h, glm::vec3 colour) {
  View v;
  v.x = x;
  v.y = y;
  v.width = w;
  v.height = h;
  v.backgroundTop = v.backgroundBottom = colour;
  v.light.shadow = false;
  return v;
}

// A camera looking down −z at the origin from z = 5.
View cameraView(int w, int h) {
  View v = flatView(0, 0, w, h, glm::vec3(0.0f));
  v.camera.position = {0, 0, 5};
  v.camera.viewFromWorld = glm::lookAt(v.camera.position, glm::vec3(0), glm::vec3(0, 1, 0));
  v.camera.clipFromView = glm::perspective(glm::radians(40.0f), float(w) / float(h), 0.1f, 20.0f);
  return v;
}

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
  EXPECT_LE(worst, 12);  // a penumbra pixel: a tap or two of sixteen
}

// The sRGB level (0–255, unrounded) of a linear value, by the exact curve.
float srgbLevel(float linear) {
  const float c = std::clamp(linear, 0.0f, 1.0f);
  return 255.0f * (c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f);
}

// A matte 4 × 4 plane at z = 0, checkered red and blue of one brightness,
// `cells` squares per side, turned so that the squares' edges cross pixels
// at every offset.
MeshItem redBlueCheckerPlane(float cells) {
  auto plane = std::make_shared<MeshData>();
  for (const glm::vec2 corner : {glm::vec2(0, 0), glm::vec2(1, 0), glm::vec2(1, 1), glm::vec2(0, 1)})
    plane->vertices.push_back({glm::vec3(4.0f * corner - 2.0f, 0.0f), glm::vec3(0, 0, 1), corner});
  plane->indices = {0, 1, 2, 0, 2, 3};
  MeshItem floor;
  floor.mesh = plane;
  floor.worldFromModel = glm::rotate(glm::mat4(1.0f), 0.3f, glm::vec3(0, 0, 1));
  floor.material.color = {0.9f, 0.05f, 0.05f};
  floor.material.color2 = {0.05f, 0.05f, 0.9f};
  floor.material.pattern = Pattern::Checker;
  floor.material.patternScale = glm::vec2(cells);
  floor.material.specular = 0.0f;
  return floor;
}

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
  post.worldFromModel = glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(1.0f, 1.5f, 0.0f)), glm::vec3(0.4f, 0.4f, 1.2f));
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

// A view whose world x, y are its normalised device coordinates (identity
// camera), placed off the image's origin so that the lines' window-space
// arithmetic is exercised away from (0, 0).
View screenView(int x, int y, int w, int h) {
  View v = flatView(x, y, w, h, glm::vec3(0.0f));
  v.camera.viewFromWorld = glm::mat4(1.0f);
  v.camera.clipFromView = glm::mat4(1.0f);
  return v;
}

// The world point that `v` draws at its pixel (px, py), top-left origin.
glm::vec3 atViewPixel(const View& v, float px, float py) {
  return {px / float(v.width) * 2.0f - 1.0f, 1.0f - py / float(v.height) * 2.0f, 0.0f};
}

// A thick white polyline on black with a 160° turn and two free ends: the
// pixels around the corner and the ends tell a capsule (round join, round
// caps) from a segment extended into a square by half its width.
TEST_F(RendererTest, PolylinesHaveRoundJoinsAndRoundCaps) {
  constexpr float kWidth = 20.0f, kHalf = kWidth / 2.0f;
  const glm::vec2 a(40.0f, 100.0f), b(160.0f, 100.0f);  // view pixels, +y down
  const float turn = glm::radians(160.0f);
  const glm::vec2 c = b + 100.0f * glm::vec2(std::cos(turn), std::sin(turn));  // back left and down
  for (int samples : {4, 1}) {
    SCOPED_TRACE(::testing::Message() << samples << " sample(s)");
    DrawList list;
    list.width = 320;
    list.height = 260;
    list.msaaSamples = samples;
    const View v = screenView(60, 30, 240, 200);
    list.views = {v};
    PolylineItem line;
    line.points = {atViewPixel(v, a.x, a.y), atViewPixel(v, b.x, b.y), atViewPixel(v, c.x, c.y)};
    line.color = {1, 1, 1, 1};
    line.widthPx = kWidth;
    line.depthTested = false;
    list.polylines.push_back(line);
    const media::Image img = renderer_->render(list);
    // The pixel that holds view point p: all its points lie within √2 of p.
    auto at = [&](glm::vec2 p) {
      return int(img.pixel(v.x + int(std::floor(p.x)), v.y + int(std::floor(p.y)))[0]);
    };
    // Whole pixels within half a width of the corner: line; beyond it,
    // where a square corner reached (|x|, |y| ≤ half a width from the
    // vertex along the first segment): background.
    for (int k = 0; k < 12; ++k) {
      const float angle = glm::radians(30.0f * float(k));
      const glm::vec2 inside = b + (kHalf - 1.5f) * glm::vec2(std::cos(angle), std::sin(angle));
      EXPECT_EQ(at(inside), 255) << "join, " << 30 * k << "°";
    }
    for (const glm::vec2 corner : {glm::vec2(8.5f, -8.5f), glm::vec2(8.5f, 8.5f)})
      EXPECT_EQ(at(b + corner), 0) << "outer corner " << corner.x << "," << corner.y;
    // The free ends: the tip along the axis is line, the square cap's
    // corner background.
    EXPECT_EQ(at(a + glm::vec2(-(kHalf - 1.5f), 0)), 255) << "start tip";
    EXPECT_EQ(at(a + glm::vec2(-8.5f, -8.5f)), 0) << "start cap corner";
    EXPECT_EQ(at(a + glm::vec2(-8.5f, 8.5f)), 0) << "start cap corner";
    const glm::vec2 along = glm::normalize(c - b), across(-along.y, along.x);
    EXPECT_EQ(at(c + (kHalf - 1.5f) * along), 255) << "end tip";
    EXPECT_EQ(at(c + 8.5f * (along + across)), 0) << "end cap corner";
    EXPECT_EQ(at(c + 8.5f * (along - across)), 0) << "end cap corner";
    // Nothing outside the view (the line's window position is its own).
    EXPECT_EQ(img.pixel(v.x - 1, v.y + int(a.y))[0], 0);
  }
}

// At one sample a line's coverage is its alpha: a thin diagonal line on
// black leaves intermediate values along its edges, and carries as much
// light per column as at 4× MSAA.
TEST_F(RendererTest, LinesAtOneSampleAreAntialiasedByCoverage) {
  DrawList list;
  list.width = 120;
  list.height = 80;
  list.views = {screenView(0, 0, 120, 80)};
  PolylineItem line;
  line.points = {atViewPixel(list.views[0], 10.0f, 20.0f), atViewPixel(list.views[0], 110.0f, 57.0f)};
  line.color = {1, 1, 1, 1};
  line.widthPx = 2.5f;
  line.depthTested = false;
  list.polylines.push_back(line);
  const media::Image multisampled = renderer_->render(list);
  list.msaaSamples = 1;
  const media::Image covered = renderer_->render(list);
  for (int x = 30; x <= 90; x += 10) {
    long long sumMulti = 0, sumCovered = 0;
    int partial = 0;
    for (int y = 0; y < 80; ++y) {
      sumMulti += multisampled.pixel(x, y)[0];
      sumCovered += covered.pixel(x, y)[0];
      partial += covered.pixel(x, y)[0] > 0 && covered.pixel(x, y)[0] < 255 ? 1 : 0;
    }
    EXPECT_GE(partial, 2) << "column " << x;
    EXPECT_NEAR(double(sumCovered), double(sumMulti), 0.15 * double(sumMulti)) << "column " << x;
  }
}

// A long straight trail of short segments at 2400 px: every column across
// it carries the same amount of line (no darker or brighter joints).
TEST_F(RendererTest, StraightPolylineHasUniformIntensityAt2400Px) {
  DrawList list;
  list.width = 2400;
  list.height = 200;
  const View v = screenView(0, 0, 2400, 200);
  list.views = {v};
  PolylineItem line;
  line.color = {1, 1, 1, 1};
  line.widthPx = 5.0f;  // the marker trail's width at this size
  // 300 segments of ≈ 7.4 px, rising 90 px over 2200 px.
  for (int k = 0; k <= 300; ++k) {
    const float t = float(k) / 300.0f;
    line.points.push_back(atViewPixel(v, 100.0f + 2200.0f * t, 145.0f - 90.0f * t));
  }
  list.polylines.push_back(line);
  const media::Image img = renderer_->render(list);
  double lo = 1e30, hi = 0.0, sum = 0.0;
  int columns = 0;
  for (int x = 150; x < 2250; ++x) {
    double column = 0.0;
    for (int y = 0; y < img.height; ++y) column += img.pixel(x, y)[0];
    lo = std::min(lo, column), hi = std::max(hi, column), sum += column;
    ++columns;
  }
  const double mean = sum / columns;
  EXPECT_GT(mean, 255.0 * 4.0);  // the line is there, about its width deep
  EXPECT_LE((hi - lo) / mean, 0.10) << "column sums from " << lo << " to " << hi;
}

// A segment that reaches between the eye and the near plane is drawn up to
// where the near plane cuts it (here, past the view's right edge); one with
// an end behind the eye is skipped whole.
TEST_F(RendererTest, PolylineThroughTheNearPlaneDrawsItsVisiblePart) {
  DrawList list;
  list.width = 160;
  list.height = 120;
  const View v = cameraView(160, 120);  // eye at z = 5, near plane 0.1 in front of it
  list.views = {v};
  PolylineItem reaching;
  reaching.points = {{-1.0f, 0.0f, 0.0f}, {0.3f, 0.0f, 4.95f}};  // 0.05 in front of the eye
  reaching.color = {1, 1, 1, 1};
  reaching.widthPx = 6.0f;
  PolylineItem behind = reaching;
  behind.points = {{-1.0f, 0.5f, 0.0f}, {0.3f, 0.5f, 6.0f}};
  list.polylines = {reaching, behind};
  const media::Image img = renderer_->render(list);
  const glm::mat4 clipFromWorld = v.camera.clipFromView * v.camera.viewFromWorld;
  auto pixelOf = [&](glm::vec3 world) {
    const glm::vec4 c = clipFromWorld * glm::vec4(world, 1.0f);
    return glm::ivec2(int((c.x / c.w * 0.5f + 0.5f) * float(v.width)), int((0.5f - c.y / c.w * 0.5f) * float(v.height)));
  };
  const glm::ivec2 start = pixelOf(reaching.points[0]);
  for (int x = start.x + 4; x < v.width; ++x) EXPECT_EQ(img.pixel(x, start.y)[0], 255) << "x = " << x;
  EXPECT_EQ(img.pixel(start.x - 6, start.y)[0], 0);  // beyond the round cap
  const glm::ivec2 skipped = pixelOf(behind.points[0]);
  for (int x = skipped.x - 4; x <= skipped.x + 4; ++x) EXPECT_EQ(img.pixel(x, skipped.y)[0], 0) << "x = " << x;
}

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
  ball.worldFromModel = glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(0.3f * float(k) - 0.8f, 0, 0.4f)),
                                   glm::vec3(0.4f));
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
// pixels, over a retained layer as in a frame drawn whole (drawImpostor's
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
    dot.worldFromModel =
        glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(-0.77f + 0.03f * float(k), 0.77f, 1.8f)), glm::vec3(0.08f));
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
  plate.worldFromModel = glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(1.6f, 1.8f, 0.3f)),
                                    glm::vec3(k < 3 ? 0.2f : 0.3f));
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
  for (int k = 0; k < kFrames; ++k)
    EXPECT_TRUE(sameBytes(inOrder.render(followFrame(k)), whole[k])) << "frame " << k;
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

TEST(ShaderLibrary, ShadersAreEmbeddedAndOverridable) {
  EXPECT_NE(ShaderLibrary{}.source("mesh.frag").find("#version 450 core"), std::string::npos);
  EXPECT_THROW((void)ShaderLibrary{"/nonexistent-shader-dir"}.source("mesh.frag"), Error);
  // The repository's shaders/ folder is a valid override (--shader-dir shaders).
  EXPECT_EQ(ShaderLibrary{test::sourceDir() / "shaders"}.source("mesh.frag"), ShaderLibrary{}.source("mesh.frag"));
}

}  // namespace
}  // namespace rollspin::render
