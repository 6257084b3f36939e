// `--shard K/N` arithmetic: N near-equal ranges that tile the clip exactly,
// names that sort, and malformed arguments refused (no GL, no encoder).
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "jobs/shard_range.hpp"

namespace rollspin::jobs {
namespace {

TEST(ShardRange, RangesTileTheClipAndDifferByAtMostOneFrame) {
  for (long long frames : {1LL, 2LL, 7LL, 30LL, 90LL, 1001LL, 10000000LL})
    for (long long n : {1LL, 2LL, 3LL, 7LL, 8LL, 64LL}) {
      if (n > frames) continue;
      long long next = 0, smallest = frames, largest = 0;
      for (long long k = 1; k <= n; ++k) {
        const FrameRange r = shardFrames({k, n}, frames);
        EXPECT_EQ(r.first, next) << frames << " frames, shard " << k << "/" << n;
        next = r.last + 1;
        smallest = std::min(smallest, r.count());
        largest = std::max(largest, r.count());
      }
      EXPECT_EQ(next, frames) << frames << " frames in " << n;
      EXPECT_LE(largest - smallest, 1) << frames << " frames in " << n;
      EXPECT_GE(smallest, 1);
    }
  EXPECT_EQ(shardFrames({2, 3}, 30).first, 10);
  EXPECT_EQ(shardFrames({2, 3}, 30).last, 19);
  EXPECT_THROW((void)shardFrames({1, 31}, 30), Error);
}

TEST(ShardRange, ParsesKOfNAndRefusesTheRest) {
  const Shard s = parseShard("3/8");
  EXPECT_EQ(s.index, 3);
  EXPECT_EQ(s.count, 8);
  for (const char* bad : {"", "3", "/8", "3/", "0/8", "9/8", "-1/8", "3/0", "3/8x", "a/b", "3:8"}) {
    try {
      (void)parseShard(bad);
      ADD_FAILURE() << "accepted " << bad;
    } catch (const Error& e) {
      EXPECT_EQ(e.exitCode(), 2) << bad;
      EXPECT_NE(std::string(e.what()).find(std::string("--shard ") + bad), std::string::npos) << e.what();
    }
  }
}

TEST(ShardRange, PartNamesSortInFrameOrder) {
  EXPECT_EQ(shardPath("output/lollipop.mp4", {2, 3}), "output/lollipop.part-2-of-3.mp4");
  EXPECT_EQ(shardPath("clip.webm", {7, 12}), "clip.part-07-of-12.webm");
  EXPECT_EQ(shardPath("a/b.c/clip.mp4", {10, 100}), "a/b.c/clip.part-010-of-100.mp4");
  EXPECT_LT(shardPath("c.mp4", {9, 12}).string(), shardPath("c.mp4", {10, 12}).string());
}

}  // namespace
}  // namespace rollspin::jobs
