// A bundled scene file and the model built from it, as the draw tests use
// them (no solver, no GL): scene text -> SceneSpec -> RollingModel.
#pragma once

#include <string>
#include <vector>

#include "model/rolling_model.hpp"
#include "support/test_files.hpp"

namespace rollspin::draw::scene_fixture {

struct Loaded {
  scene::SceneSpec spec;
  model::RollingModel model;
};

// `relative` to the source tree (e.g. "scenes/lollipop.toml"), with `--set` overrides.
inline Loaded load(const std::string& relative, const std::vector<std::string>& overrides = {}) {
  Loaded l{model::loadScene((test::sourceDir() / relative).string(), overrides), {}};
  l.model = model::buildSceneModel(l.spec);
  return l;
}

}  // namespace rollspin::draw::scene_fixture
