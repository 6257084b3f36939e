// Fuzzes the scene loader with --set overrides and the model built from it.
// Input: TOML text, then optional overrides, separated by NUL bytes. Any
// rollspin::Error is a correct answer; a crash, a sanitizer report, an
// escaped exception of another type or a hang is a bug.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "geometry/uv_curve.hpp"
#include "model/rolling_model.hpp"
#include "motion/solve_job.hpp"
#include "scene/scene_loader.hpp"

namespace {
// Ten times the most any scene in scenes/ needs (48); some 20 ms each here.
constexpr std::size_t kPanelsPerInput = 500;
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string input(reinterpret_cast<const char*>(data), size);
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const std::size_t nul = input.find('\0', start);
    parts.push_back(input.substr(start, nul == std::string::npos ? std::string::npos : nul - start));
    if (nul == std::string::npos) break;
    start = nul + 1;
  }
  const std::vector<std::string> overrides(parts.begin() + 1, parts.end());
  // Building a path costs about its panels, and a scene may ask for any
  // number (a uv curve over t in [0, 26000] takes 17 s in Release, several
  // minutes here): work, not a bug. Bounded per input, as an image decoder's
  // fuzzer bounds the pixels it decodes.
  const rollspin::geometry::PanelBudget budget(kPanelsPerInput);
  try {
    const rollspin::scene::SceneSpec spec = rollspin::scene::loadSceneText(parts[0], "<fuzz>", overrides);
    const rollspin::model::RollingModel model = rollspin::model::buildModel(spec);
    (void)rollspin::motion::chooseSolver(spec, model);
    (void)rollspin::motion::timelineArcLengths(spec, model).size();
  } catch (const rollspin::Error&) {
    // bad input, reported properly
  }
  return 0;
}
