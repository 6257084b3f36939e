// The renderer tests' shared fixtures: one GL context (and renderer) for the
// suite (ROLLSPIN_GL chooses the backend), and the views and materials that
// several passes' tests draw.
#pragma once

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

#include "render/gl_context.hpp"
#include "render/mesh_builders.hpp"
#include "render/renderer.hpp"

namespace rollspin::render {

// A GL context and nothing else, for the renderer's internals (its GL
// objects, programs, caches and targets) tested one by one.
class GlContextTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { context_ = createContext().release(); }
  static void TearDownTestSuite() { delete context_; }
  inline static GlContext* context_ = nullptr;
};

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
  inline static GlContext* context_ = nullptr;
  inline static Renderer* renderer_ = nullptr;
};

inline View flatView(int x, int y, int w, int h, glm::vec3 colour) {
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
inline View cameraView(int w, int h) {
  View v = flatView(0, 0, w, h, glm::vec3(0.0f));
  v.camera.position = {0, 0, 5};
  v.camera.viewFromWorld = glm::lookAt(v.camera.position, glm::vec3(0), glm::vec3(0, 1, 0));
  v.camera.clipFromView = glm::perspective(glm::radians(40.0f), float(w) / float(h), 0.1f, 20.0f);
  return v;
}

// The sRGB level (0–255, unrounded) of a linear value, by the exact curve.
inline float srgbLevel(float linear) {
  const float c = std::clamp(linear, 0.0f, 1.0f);
  return 255.0f * (c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f);
}

// A matte 4 × 4 plane at z = 0, checkered red and blue of one brightness,
// `cells` squares per side, turned so that the squares' edges cross pixels
// at every offset.
inline MeshItem redBlueCheckerPlane(float cells) {
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

}  // namespace rollspin::render
