// VideoWriter — one video file through the FFmpeg libraries, in-process
// (libavformat + libavcodec + libswscale), following FFmpeg's
// doc/examples/mux.c: send_frame / receive_packet, packet timestamps
// rescaled from the codec's den/num (one tick per frame) to the stream's
// time base, a flushed encoder (null frame) and the trailer. The container,
// encoder, pixel format and options come from VideoSettings, filled by each
// format's sink file (mp4_writer, webm_writer, mov_writer, gif_writer).
// RGBA is converted with the BT.709 matrix (full-range RGB → limited-range
// YUV, alpha kept when the pixel format has it) and tagged BT.709 (colour
// space, primaries, transfer) and limited range, so browsers and players
// show the colours that were rendered. 8-bit 4:2:0 (H.264, VP9) goes
// through Yuv420Converter, which converts only the blocks that changed
// since the last frame; 4:2:2 and 4:4:4 10-bit (ProRes) through swscale.
// Captions go in a text subtitle stream beside the video (subtitle_track.hpp).
// The file is written under a temporary name in the same folder and renamed
// on finish(); finishPartial() completes what was written as a shorter,
// playable NAME.partial.EXT; destroyed unfinished, it removes its file. A
// device (e.g. /dev/full) is written in place.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "media/frame_sink.hpp"
#include "media/subtitle_track.hpp"

struct AVFrame;  // libavutil: only gif_writer hands frames in directly

namespace rollspin::media {

using OptionList = std::vector<std::pair<std::string, std::string>>;

struct VideoSettings {
  int width = 0, height = 0;
  int fpsNum = 30, fpsDen = 1;  // frames per second as a rational (30000/1001 for NTSC 29.97)
  std::string container;        // libavformat muxer: "mp4", "webm", "mov", "gif"
  std::string encoder;          // libavcodec encoder: "libx264", "libvpx-vp9", "prores_aw", "gif"
  std::string pixelFormat;      // the encoder's input: "yuv420p", "yuva420p", "yuva444p10le", "pal8"
  bool evenSize = true;         // chroma subsampling: width and height must be even
  bool yuvBt709 = true;         // BT.709 matrix and tags, limited range (false: RGB/palette formats)
  OptionList codecOptions;      // av_opt_set on the encoder ("crf", "preset", "profile", …)
  OptionList muxerOptions;      // given to avformat_write_header ("movflags", "loop", …)
  OptionList streamMetadata;    // the stream's tags ("alpha_mode" = "1" for WebM with alpha)
  // The container's own tags (title, comment, …): set on the format context
  // before the header is written. The one place for file-level metadata.
  OptionList containerMetadata;
  std::string describe;  // for error messages: "H.264 (libx264, crf 18, preset medium)"
  // A subtitle track: its libavcodec encoder ("mov_text" for MP4/MOV,
  // "webvtt" for WebM; "" = none) and its cues, in this file's frames; each
  // cue is muxed as its first frame is written. No cues: no track.
  std::string subtitleEncoder;
  SubtitleCues subtitles;
  bool subtitlesByDefault = false;  // the track's "default" flag: players show it unasked
};

class VideoWriter : public FrameSink {
 public:
  // Opens the encoder and the output and writes the header. Throws Error:
  // BadInput for an odd (where it matters) or zero size, Runtime when the
  // encoder or muxer is missing or refuses the settings, or the file cannot
  // be created.
  VideoWriter(std::filesystem::path finalPath, const VideoSettings& settings);
  ~VideoWriter() override;  // unfinished: removes the temporary file
  VideoWriter(const VideoWriter&) = delete;
  VideoWriter& operator=(const VideoWriter&) = delete;

  // The frame must have the writer's size; alpha is kept only when the
  // pixel format has an alpha plane.
  void write(const ImageView& frame) override;
  std::filesystem::path finish() override;
  std::filesystem::path finishPartial() override;  // "NAME.partial.EXT"
  [[nodiscard]] long long framesWritten() const override;
  // With the changed-blocks converter: the share of the pixels it converted.
  [[nodiscard]] std::string verboseSummary() const override;
  [[nodiscard]] bool carriesSubtitles() const override;

 protected:
  // Encodes a frame already in the encoder's pixel format; its pts is set
  // here (one tick per frame). For sinks that convert on their own (GIF).
  void writeConverted(AVFrame* frame);
  [[nodiscard]] const std::filesystem::path& finalPath() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// "dir/NAME.partial.EXT" for "dir/NAME.EXT".
[[nodiscard]] std::filesystem::path partialName(const std::filesystem::path& finalPath);

}  // namespace rollspin::media
