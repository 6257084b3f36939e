#include "jobs/shard_range.hpp"

#include <fmt/format.h>

#include <charconv>

#include "core/error.hpp"

namespace rollspin::jobs {

namespace {
SourceLoc shardLoc(const Shard& s) { return {fmt::format("--shard {}/{}", s.index, s.count)}; }
}  // namespace

Shard parseShard(const std::string& text) {
  const SourceLoc loc{"--shard " + text};
  const auto slash = text.find('/');
  auto parse = [](const std::string& part, long long& out) {
    const auto [ptr, ec] = std::from_chars(part.data(), part.data() + part.size(), out);
    return !part.empty() && ec == std::errc() && ptr == part.data() + part.size();
  };
  Shard s;
  if (slash == std::string::npos || !parse(text.substr(0, slash), s.index) || !parse(text.substr(slash + 1), s.count))
    throw badInput(loc, "expected --shard K/N: the K-th of N parts, 1-based (e.g. --shard 2/8)");
  if (s.count < 1 || s.index < 1 || s.index > s.count)
    throw badInput(loc, "expected 1 <= K <= N in --shard K/N, got K = {}, N = {}", s.index, s.count);
  return s;
}

FrameRange shardFrames(const Shard& s, long long frameCount) {
  if (s.count > frameCount)
    throw badInput(shardLoc(s), "this clip has {} frames, fewer than the {} parts asked for", frameCount, s.count);
  // Floor division of the clip at K/N: integer arithmetic, so every machine
  // computes the same boundaries (frameCount ≤ 1e7, no overflow).
  return {(s.index - 1) * frameCount / s.count, s.index * frameCount / s.count - 1};
}

std::filesystem::path shardPath(const std::filesystem::path& clipPath, const Shard& s) {
  const int width = static_cast<int>(std::to_string(s.count).size());
  std::filesystem::path out = clipPath;
  out.replace_filename(fmt::format("{}.part-{:0{}}-of-{}{}", clipPath.stem().string(), s.index, width, s.count,
                                   clipPath.extension().string()));
  return out;
}

}  // namespace rollspin::jobs
