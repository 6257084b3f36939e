// Output formats — what rollspin can write (output_formats.def, one row per
// format) and the one rule that picks a format from render.format and the
// -o path. Libav-free: the scene loader validates names against this table;
// the sinks themselves are opened by sink_factory.hpp.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "core/error.hpp"

namespace rollspin::media {

enum class OutputKind {
  Still,        // one raster image (ImageView sink of one frame)
  Video,        // one file of frames
  FrameFolder,  // a folder of numbered images
  Figure,       // one image drawn as vectors (PDF/SVG): not an ImageView sink
  Viewer,       // one interactive page of the whole path (HTML, jobs/viewer_job): not an ImageView sink
};
enum class AlphaSupport { None, Binary, Full };
// What a job produces: one image or a clip. Stills and figures serve the
// first, videos and frame folders the second.
enum class OutputUse { Still, Animation };

struct OutputFormat {
  std::string_view name;        // render.format
  std::string_view extensions;  // ".jpg .jpeg"; "" = a folder
  OutputKind kind;
  AlphaSupport alpha;
  bool evenSize;     // 4:2:0 / 4:2:2 chroma: even width and height
  int fpsCap;        // 0 = none
  int defaultWidth;  // 0 = the scene's size
  bool shards;       // --shard K/N parts come together again (join, or one folder)

  [[nodiscard]] constexpr OutputUse use() const {
    return kind == OutputKind::Still || kind == OutputKind::Figure ? OutputUse::Still : OutputUse::Animation;
  }
  [[nodiscard]] constexpr bool isFolder() const { return extensions.empty(); }
  // MP4 is H.264 (mp4_writer.cpp): its frames obey H.264's levels (h264_levels.hpp).
  [[nodiscard]] constexpr bool encodesH264() const { return name == "mp4"; }
  // ".mp4": the first extension ("" for a folder).
  [[nodiscard]] std::string defaultExtension() const;
  [[nodiscard]] bool hasExtension(std::string_view lowerCaseExtension) const;
};

#define ROLLSPIN_OUTPUT_FORMAT(name, extensions, kind, alpha, even, fpsCap, defaultWidth, shards, factory) \
  OutputFormat{name, extensions, OutputKind::kind, AlphaSupport::alpha, even, fpsCap, defaultWidth, shards},
inline constexpr std::array kOutputFormats{
#include "media/output_formats.def"
};
#undef ROLLSPIN_OUTPUT_FORMAT

// The row of `name` that serves `use`, or nullptr.
[[nodiscard]] const OutputFormat* findOutputFormat(std::string_view name, OutputUse use);
// Whether any row is called `name` (what render.format accepts).
[[nodiscard]] bool isOutputFormatName(std::string_view name);
// "\"mp4\", \"webm\", …": every distinct name, for messages.
[[nodiscard]] std::string outputFormatNames();
// "mp4 (.mp4), webm (.webm), …, png (a folder of frames)": the rows serving `use`.
[[nodiscard]] std::string describeFormats(OutputUse use);

// The format of a job's output. `requested` is render.format (at
// `requestedAt`); `output` the -o path ("" = the default name). Rules:
//   - render.format wins; an -o extension that contradicts it is bad input.
//     A still ignores a render.format that names only animation formats
//     (the key describes the clip), and an animation refuses a still format.
//   - otherwise the -o extension; an animation's folder (no extension, or an
//     existing directory) is PNG frames; a still without an extension is PNG.
//   - otherwise mp4 for an animation, png for a still.
// An extension of the other kind (--still -o x.mp4, a clip to .jpg) or an
// unknown one throws BadInput naming the formats that fit.
[[nodiscard]] const OutputFormat& chooseFormat(const std::optional<std::string>& requested,
                                               const SourceLoc& requestedAt, const std::filesystem::path& output,
                                               OutputUse use);

}  // namespace rollspin::media
