// openSink — the one way a job opens its output: the format's row
// (output_format.hpp) names its factory, which builds the sink from
// SinkOptions. Each sink file defines its own factory (declared here from
// the table, output_formats.def).
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "media/frame_sink.hpp"
#include "media/output_format.hpp"
#include "media/output_metadata.hpp"
#include "media/video_writer.hpp"

namespace rollspin::media {

// Everything any format may need; each factory reads what applies to it.
struct SinkOptions {
  std::filesystem::path path;  // the final name (a folder for frame folders)
  int width = 0, height = 0;
  int fpsNum = 30, fpsDen = 1;             // exact rational frames per second
  bool alpha = false;                      // keep transparency (render.transparent)
  std::optional<double> crf;               // animation.crf when the scene sets it; else the format's default
  std::string preset = "medium";           // animation.preset (x264's names; other encoders map them)
  bool loop = true;                        // animation.loop: a GIF plays forever (else once)
  int jpegQuality = 92;                    // render.jpeg_quality
  long long firstIndex = 0;                // frame folders: the first frame's index in the clip
  bool wholeClip = true;                   // frame folders: the whole clip (stale frames go) or a part
  OptionList containerMetadata;            // file-level tags of video containers (VideoSettings)
  SubtitleCues subtitles;                  // MP4, WebM, MOV: the captions' track (VideoSettings), in this file's frames
  bool subtitlesByDefault = false;         // the track shows unasked (when the pixels carry no captions)
  std::optional<OutputMetadata> metadata;  // stills and GIF: written into the file (none: --no-metadata)
};

// Opens the sink of `format`. Throws Error like the sink's constructor;
// Runtime for a format with no raster sink (a Figure).
[[nodiscard]] std::unique_ptr<FrameSink> openSink(const OutputFormat& format, const SinkOptions& options);

// The factory of a row whose writer is not an ImageView sink (kind Figure):
// throws Runtime. Such rows are written by their own backend.
[[nodiscard]] std::unique_ptr<FrameSink> noRasterSink(const SinkOptions& options);

#define ROLLSPIN_OUTPUT_FORMAT(name, extensions, kind, alpha, even, fpsCap, defaultWidth, shards, factory) \
  [[nodiscard]] std::unique_ptr<FrameSink> factory(const SinkOptions& options);
#include "media/output_formats.def"
#undef ROLLSPIN_OUTPUT_FORMAT

}  // namespace rollspin::media
