// A draw list for the retained layer's plain-data tests (layer_key_test,
// layer_plan_test): two views side by side, 320×160 each, looking down at
// the plane z = 0 through an orthographic camera, so that world x, y ∈
// [−4, 4] × [−2, 2] fill a view. No items: each test adds its own.
#pragma once

#include <glm/gtc/matrix_transform.hpp>

#include "render/draw_list.hpp"

namespace rollspin::render::test {

inline DrawList twoViewsLookingDown() {
  DrawList list;
  list.width = 640;
  list.height = 160;
  for (int i = 0; i < 2; ++i) {
    View v;
    v.x = 320 * i;
    v.width = 320;
    v.height = 160;
    v.camera.position = {0, 0, 5};
    v.camera.viewFromWorld = glm::lookAt(v.camera.position, glm::vec3(0), glm::vec3(0, 1, 0));
    v.camera.clipFromView = glm::ortho(-4.0f, 4.0f, -2.0f, 2.0f, 0.1f, 20.0f);
    list.views.push_back(v);
  }
  return list;
}

}  // namespace rollspin::render::test
