// The set-up every drawing job shares — a still, a figure, an animation —
// in one order: the size flags (checked, then applied after --set so errors
// name them), the scene, the output format and what its row asks of the scene
// (a GIF's width and frame-rate cap), the output path, the frame-memory
// check, the model; later the drawer (ball texture, facts) and one GL
// renderer. Each job adds only what is its own (a clip's clock and sink, a
// still's arc length, a figure's vector pass).
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "draw/scene_drawer.hpp"
#include "jobs/flag_overrides.hpp"
#include "media/output_format.hpp"
#include "model/rolling_model.hpp"
#include "render/gl_context.hpp"
#include "render/renderer.hpp"
#include "render/shader_library.hpp"
#include "scene/scene_spec.hpp"

namespace rollspin::jobs {

struct DrawJobRequest {
  std::string scenePath;
  std::vector<std::string> overrides;      // --set
  std::vector<FlagOverride> presetFlags;   // --quality: before --width/--height
  std::optional<long long> width, height;  // --width, --height: [1, 8192]
  bool transparent = false;                // --transparent
  std::filesystem::path output;            // -o ("" = the job's default name)
  media::OutputUse use = media::OutputUse::Still;
  std::uint64_t extraBytesPerPixel = 0;  // what the job adds to the renderer's frame memory
  std::optional<std::string> sceneText;  // the scene itself (Python's loads()); scenePath names it
  std::string sceneName{};               // with sceneText: the scene's name ("" = "scene")
};

struct DrawJob {
  scene::SceneSpec spec;
  const media::OutputFormat* format = nullptr;
  model::RollingModel model;
  draw::FigureText figureText;  // a clip's text, or a figure's (fitTextToFigure)
};

// Everything up to the model; throws BadInput naming the flag, key or -o.
[[nodiscard]] DrawJob prepareDrawJob(const DrawJobRequest& request);

// The drawer of a job: the ball texture (none for the twin alone) and the
// scene's facts. `figureStillAt`: a figure of the still at that arc length
// (SceneDrawer: framed for that still alone).
[[nodiscard]] std::unique_ptr<draw::SceneDrawer> makeDrawer(const DrawJob& job,
                                                            std::optional<double> figureStillAt = std::nullopt);

// One GL context, its shaders and the renderer over them, in that order.
struct GlRenderer {
  // The context from render.backend / render.device (else ROLLSPIN_GL, ROLLSPIN_EGL_DEVICE).
  GlRenderer(const scene::SceneSpec& spec, const std::filesystem::path& shaderDir);
  std::unique_ptr<render::GlContext> context;
  render::ShaderLibrary shaders;
  render::Renderer renderer;
};

}  // namespace rollspin::jobs
