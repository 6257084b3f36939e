// joinParts — the parts of a split render (`render --shard K/N` or
// `--frames A:B`, each a video file with ContainerTags) made one clip,
// in-process with libavformat: stream copy, no re-encode.
// Before anything is written it checks, naming the part and what differs:
//   each part carries rollspin's tags, one video stream, and as many frames
//   as its tagged range; its first packet is a keyframe and its frames sit
//   one frame apart;
//   all parts share the container, rollspin version, size, encoder settings
//   (encoder, preset, rate factor, frame rate), the scene (SHA-256 of its
//   resolved text), the clip's frame count, the codec, its extradata
//   (SPS/PPS: a decoder needs one set for the whole stream) and time base;
//   sorted by first frame the ranges cover 0 … total − 1 with no gap and no
//   overlap.
// A subtitle track (captions) is optional, but all parts have one or none,
// of one codec; each part's track holds its own frames' cues, so a cue that
// a part boundary cut in two is joined again (same text, touching ends).
// The timestamps are rewritten into one timeline (frame k at k·den/num s, as
// a whole render; decoding times one frame a packet across the joins, a part
// with less B-frame delay than another's moved to the larger delay), the
// joined clip is tagged as frames 0 … total − 1 (so it can itself be joined,
// or checked, again), MP4/MOV get +faststart, and the file is written under a
// temporary name and renamed when complete.
// Anything that does not fit throws Error BadInput (exit 2); a failing write
// throws Runtime (exit 1); neither leaves a file behind.
#pragma once

#include <filesystem>
#include <functional>
#include <vector>

#include "media/subtitle_track.hpp"

namespace rollspin::media {

struct JoinSummary {
  std::filesystem::path written;
  long long frames = 0;
  int width = 0, height = 0;
  int fpsNum = 0, fpsDen = 0;
  SubtitleCues cues;  // the joined subtitle track's, in the clip's frames (for its sidecar files)
};

// `stop` is polled between packets (a Ctrl-C): when it returns true the join
// ends, removes its temporary file and returns a summary with no `written`.
JoinSummary joinParts(const std::vector<std::filesystem::path>& parts, const std::filesystem::path& output,
                      const std::function<bool()>& stop = {});

}  // namespace rollspin::media
