// Animation job: scene file → frames at the exact arc lengths s(t_k) of the
// FrameClock → a video (MP4, WebM, GIF, MOV) or a folder of PNG frames,
// opened through media's output-format table (sink_factory.hpp). A sink that
// needs the clip first (a GIF's palette) gets a first pass over the frames
// it names. Streaming: the
// main thread solves and renders frame after frame (the GL context lives on
// it) while a second thread converts and encodes, with a small bounded queue
// between them, so both cores work and memory does not grow with the clip.
// SIGINT/SIGTERM stop between frames and leave a shorter, valid output under
// a name that says so (or nothing); errors leave nothing at the final name.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "media/subtitle_track.hpp"

namespace rollspin::jobs {

struct AnimationOptions {
  std::string scenePath;
  std::vector<std::string> overrides;  // --set
  std::filesystem::path output;        // "" → output/<scene>.EXT or output/<scene>/
  std::optional<std::string> frames;   // "A:B", inclusive
  std::optional<std::string> shard;    // "K/N": the K-th of N near-equal ranges (shard_range.hpp)
  std::optional<std::string> quality;  // low | medium | high | 4k
  std::optional<long long> width, height;
  bool transparent = false;
  bool quiet = false;
  // A whole MP4, WebM or MOV clip's captions beside it: NAME.vtt (and NAME.srt).
  media::SidecarFormats sidecars = media::SidecarFormats::Vtt;
  std::filesystem::path shaderDir;
  std::optional<std::string> sceneText;  // the scene itself (Python's loads()); scenePath names it
  std::string sceneName;                 // with sceneText from --from: the scene's name
  bool metadata = true;                  // false: --no-metadata (remembered_output.hpp)
  // Called on the rendering thread after each frame is handed on (done, of
  // total including a GIF's palette pass); the Python binding's progress bar.
  std::function<void(long long done, long long total)> onFrame;
};

struct AnimationResult {
  std::filesystem::path written;  // empty when interrupted before any frame
  long long framesWritten = 0;
  long long framesRequested = 0;
  int interruptedBy = 0;  // the signal, or 0
};

// Quality presets (Manim's spirit): size and frame rate.
struct QualityPreset {
  const char* name;
  int width, height, fps;
};
[[nodiscard]] const QualityPreset* findQualityPreset(const std::string& name);

AnimationResult renderAnimation(const AnimationOptions& options);

}  // namespace rollspin::jobs
