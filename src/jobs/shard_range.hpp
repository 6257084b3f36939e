// `render --shard K/N`: the K-th (1-based) of N near-equal, contiguous frame
// ranges of a clip of F frames, frames ⌊(K−1)·F/N⌋ … ⌊K·F/N⌋ − 1 (sizes differ
// by at most one; together they cover 0 … F − 1 exactly once), and the name
// of its output, NAME.part-K-of-N.EXT with K zero-padded to N's width so the
// parts sort in frame order.
#pragma once

#include <filesystem>
#include <string>

#include "motion/frame_clock.hpp"

namespace rollspin::jobs {

using motion::FrameRange;

struct Shard {
  long long index = 1, count = 1;  // K of N
};

// "K/N" with 1 <= K <= N; throws BadInput naming `--shard TEXT`.
[[nodiscard]] Shard parseShard(const std::string& text);

// Throws BadInput (naming --shard) when the clip has fewer frames than shards.
[[nodiscard]] FrameRange shardFrames(const Shard& shard, long long frameCount);

// "dir/NAME.EXT" → "dir/NAME.part-K-of-N.EXT".
[[nodiscard]] std::filesystem::path shardPath(const std::filesystem::path& clipPath, const Shard& shard);

}  // namespace rollspin::jobs
