// ContainerTags — what a rendered clip, or one part of a split render, says
// about itself in its container metadata (MP4/MOV: `mdta` keys through
// movflags +use_metadata_tags; Matroska/WebM: tags), so that `rollspin join`
// can check that parts belong together before copying their streams:
//   rollspin_scene_sha256   SHA-256 of the resolved scene text (`scene --print`'s TOML)
//   rollspin_version        the rollspin that rendered it
//   rollspin_encoder        encoder, preset, rate factor, pixel format, size, frame rate
//   rollspin_frames         "FIRST-LAST": the frames it holds (0-based, inclusive)
//   rollspin_clip_frames    the whole clip's frame count
// The writer only copies the tags in; the app decides their values.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/error.hpp"

struct AVFormatContext;
struct AVDictionary;

namespace rollspin::media {

struct ContainerTags {
  std::string sceneSha256;
  std::string version;
  std::string encoderSettings;
  long long firstFrame = 0, lastFrame = 0;  // inclusive
  long long clipFrames = 0;

  [[nodiscard]] long long frameCount() const { return lastFrame - firstFrame + 1; }
  [[nodiscard]] bool operator==(const ContainerTags&) const = default;
};

// The tags as (key, value) pairs in the order above.
[[nodiscard]] std::vector<std::pair<std::string, std::string>> containerMetadata(const ContainerTags& tags);

// Reads them back from a container's metadata; nullopt when a key is missing
// or malformed (not a rollspin render, or an older one). `error` says which.
[[nodiscard]] std::optional<ContainerTags> parseContainerTags(const std::map<std::string, std::string>& metadata,
                                                              std::string* error = nullptr);

// Sets the tags on an output format context before avformat_write_header,
// and adds +use_metadata_tags to `muxerOptions`' movflags when the muxer has
// that option (MP4 and MOV keep only a few iTunes keys otherwise).
void applyContainerTags(AVFormatContext* format, const ContainerTags& tags, AVDictionary** muxerOptions);
// Only the movflags part: lets MP4/MOV keep custom keys already set on `format`.
void allowCustomContainerKeys(AVFormatContext* format, AVDictionary** muxerOptions);

// An interrupted render keeps only its first `framesWritten` frames: when
// `format` carries rollspin's tags, its frames tag is made to say so
// (FIRST-(FIRST + framesWritten - 1)). Returns the tag's value before and
// after, or nullopt when the metadata carries no rollspin tags. Call it
// before the trailer: MP4 and MOV write their metadata there; Matroska wrote
// it with the header (see patchMatroskaFramesTag).
struct FramesRetag {
  std::string before, after;  // "0-929" → "0-336"
};
[[nodiscard]] std::optional<FramesRetag> retagPartial(AVFormatContext* format, long long framesWritten);

// Matroska/WebM write their tags with the header: overwrites the frames
// tag's value in the finished file at `path` with `value` (no longer than the
// old one; EBML strings may end in zero bytes, which readers drop). False
// when the old value is not found exactly once.
bool patchMatroskaFramesTag(const std::filesystem::path& path, const std::string& oldValue, const std::string& value);

// Every file-level tag of the media file at `path` (keys in lower case), for
// `--from`: BadInput at `where` when libavformat cannot open it.
[[nodiscard]] std::map<std::string, std::string> readContainerMetadata(const std::filesystem::path& path,
                                                                       const SourceLoc& where);

// Lower-case hex SHA-256 of `text` (libavutil's implementation).
[[nodiscard]] std::string sha256Hex(const std::string& text);

}  // namespace rollspin::media
