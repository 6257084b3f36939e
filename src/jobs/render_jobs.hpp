// Render jobs: a still image of a scene at one arc length, from scene file to
// PNG or JPEG (media/output_format.hpp). Kept apart from the CLI so tests and benchmarks can call it; the GL
// context is created here and nowhere on the solve/timeline path.
#pragma once

#include <cstdint>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "draw/scene_drawer.hpp"
#include "media/image_view.hpp"
#include "media/sink_factory.hpp"
#include "model/rolling_model.hpp"
#include "render/draw_list.hpp"
#include "render/gl_context.hpp"
#include "scene/scene_spec.hpp"

namespace rollspin::jobs {

using model::RollingModel;

// Where along the path: `--at s=VALUE` or `--at fraction=F`.
struct ArcPosition {
  enum class Kind { ArcLength, Fraction } kind = Kind::Fraction;
  double value = 0.5;
};
// Parses "s=1.5" / "fraction=0.25"; throws BadInput naming the argument.
[[nodiscard]] ArcPosition parseArcPosition(const std::string& text);
// The arc length in [0, L]; throws BadInput when outside.
[[nodiscard]] double resolveArcPosition(const ArcPosition& at, double length, const std::string& argument);

// The ball texture named by ball.texture (resolved against the scene file's
// folder, or the working directory for --set), or null for the built-in one.
// A missing or corrupt file is BadInput at ball.texture.
[[nodiscard]] std::shared_ptr<const render::TextureImage> loadBallTexture(const scene::SceneSpec& spec);

struct StillOptions {
  std::string scenePath;
  std::vector<std::string> overrides;
  std::optional<std::string> at;  // "s=..." | "fraction=..."; default: middle (end for a strobe)
  std::filesystem::path output;   // default output/<scene>.png
  std::optional<long long> width, height;
  bool transparent = false;
  std::filesystem::path shaderDir;
  // With a figure output: also writes its layout (render::figureLayoutJson:
  // plates, text boxes, arrows and paths in page points) to this file.
  std::filesystem::path layoutJson;
  // --from an output (remembered_output.hpp): the scene's text, its name and
  // the job's figure layout (nullopt: the scene's [figure] keys decide).
  std::optional<std::string> sceneText;
  std::string sceneName;
  std::optional<bool> figureLayout;
  bool metadata = true;  // false: --no-metadata
};

// Renders one still and writes it; returns the path written.
// Refuses (BadInput, with the numbers) a frame size whose buffers would not
// fit in the memory available to the process.
// extraBytesPerPixel: what a job adds per pixel beyond the renderer (an
// animation's frame queue, colour conversion and x264's look-ahead).
void checkFrameMemory(const scene::SceneSpec& spec, std::uint64_t extraBytesPerPixel = 0);
// What the renderer's buffers take for `pixels` pixels at `msaa` samples,
// as checkFrameMemory counts them, and under ulimit -v the GL driver's own
// address space (jobs/address_space.hpp).
[[nodiscard]] std::uint64_t rendererBytes(std::uint64_t pixels, int msaa);

// The job's output format (media/output_format.hpp: render.format, the -o
// extension), after the checks the format imposes on the scene: alpha it
// cannot hold (render.transparent) and odd sizes where chroma is subsampled
// are BadInput naming the key.
[[nodiscard]] const media::OutputFormat& chooseOutputFormat(const scene::SceneSpec& spec,
                                                            const std::filesystem::path& output, media::OutputUse use);

// The options every sink reads from the scene (size, alpha, crf, preset,
// loop, JPEG quality); the job adds the frame rate and the clip range.
[[nodiscard]] media::SinkOptions sinkOptions(const scene::SceneSpec& spec, const std::filesystem::path& path);

std::filesystem::path renderStill(const StillOptions& options);

struct DrawJob;
// The still's DrawList at `at` (default: the middle, the end for a strobe),
// as renderStill draws it: no GL. A figure's layout follows the job's spec
// (fitTextToFigure first).
[[nodiscard]] render::DrawList drawStill(const DrawJob& job, const std::optional<std::string>& at);

struct DrawJob;  // job_setup.hpp
// The arc length a still shows: `at` ("s=…" | "fraction=…"), else the middle
// of the path (its end for a strobe); BadInput naming --at when outside.
[[nodiscard]] double stillArcLength(const DrawJob& job, const std::optional<std::string>& at);
// The still's poses at arc length s (solved from 0 to s), marked as a still.
[[nodiscard]] motion::FrameOrientations stillFrame(const DrawJob& job, double s);

// The GL context the scene asks for: render.backend / render.device with
// where they were given (unset: the environment decides, render/gl_context.hpp).
[[nodiscard]] render::ContextRequest contextRequest(const scene::SceneSpec& spec);

}  // namespace rollspin::jobs
