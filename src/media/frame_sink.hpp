// FrameSink — where an animation's frames go: one ImageView at a time, in
// order, never knowing where the pixels came from. Implementations: a video
// file (video_writer.hpp: MP4, WebM, MOV; gif_writer.hpp), a folder of PNG
// frames (png_sequence.hpp) and a still image (still_image_sink.hpp); one
// factory opens them all (sink_factory.hpp).
// A sink is either finished (the output is complete at its final name),
// finished early (what was written so far, as a valid output under a name
// that says so), or destroyed unfinished (it removes what it started).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "media/image_view.hpp"

namespace rollspin::media {

class FrameSink {
 public:
  virtual ~FrameSink() = default;
  // Appends one frame; throws Error (Runtime) when it cannot be written.
  virtual void write(const ImageView& frame) = 0;
  // Completes the output at its final name and returns that name.
  virtual std::filesystem::path finish() = 0;
  // Completes the frames written so far as a shorter, valid output under a
  // name saying it is partial, and returns that name; returns an empty path
  // (and leaves nothing) when no frame was written.
  virtual std::filesystem::path finishPartial() = 0;
  [[nodiscard]] virtual long long framesWritten() const = 0;
  // One line for --verbose on what the sink did beyond writing frames
  // ("converted 9.1 % of the pixels …"); empty: nothing to say.
  [[nodiscard]] virtual std::string verboseSummary() const { return {}; }
  // Whether the format has a subtitle track (MP4, WebM, MOV): such a clip
  // also gets its captions as sidecar files (subtitle_track.hpp).
  [[nodiscard]] virtual bool carriesSubtitles() const { return false; }

  // A sink that must see the clip before writing it (a GIF's palette) names
  // the frames it wants first: indices in [0, count) of the `count` frames it
  // will be given, in increasing order; the caller passes them to preview()
  // and then every frame to write(). Empty (the default): no first pass.
  [[nodiscard]] virtual std::vector<long long> previewFrames(long long /*count*/) const { return {}; }
  virtual void preview(const ImageView& /*frame*/) {}
};

}  // namespace rollspin::media
