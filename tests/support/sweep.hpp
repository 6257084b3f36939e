// How much of a sweep a test walks: every item in the Release pass, a
// deterministic quarter under ROLLSPIN_TEST_SWEEP=sample. A sweep test checks
// one property over many data (every scene × aspect × frame); the sanitizer
// and EGL passes are there for the code paths, which a sample reaches at a
// quarter of the cost (scripts/sanitize.sh and scripts/test.sh set it).
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace rollspin::test {

// True under ROLLSPIN_TEST_SWEEP=sample; false when unset or "full". Any
// other value is a mistake in a script: the test aborts, saying so.
bool sweepSampled();

// Indices of `count` items that a sweep visits: all of them, or under
// sampling every kSweepStride-th one, starting at an offset taken from the
// running test's name (so two sweep tests sample different items, and one
// test samples the same items on every run). Never empty when count > 0.
inline constexpr std::size_t kSweepStride = 4;
std::vector<std::size_t> sweepIndices(std::size_t count);

// The same as a mask: visited[i] says whether item i is in the sweep (for a
// loop that draws every item's random numbers but checks only the sample).
std::vector<bool> sweepMask(std::size_t count);

template <class T>
std::vector<T> sweep(const std::vector<T>& items) {
  std::vector<T> kept;
  for (std::size_t i : sweepIndices(items.size())) kept.push_back(items[i]);
  return kept;
}

// The scene files in scenes/, sorted by name (the whole set, not sampled).
std::vector<std::filesystem::path> bundledSceneFiles();

}  // namespace rollspin::test
