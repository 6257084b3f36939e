#include "support/sweep.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <iostream>

#include "support/test_files.hpp"

namespace rollspin::test {

bool sweepSampled() {
  const char* mode = std::getenv("ROLLSPIN_TEST_SWEEP");
  if (mode == nullptr || std::string(mode).empty() || std::string(mode) == "full") return false;
  if (std::string(mode) == "sample") return true;
  std::cerr << "ROLLSPIN_TEST_SWEEP=" << mode << ": expected 'full' or 'sample'\n";
  std::abort();
}

std::vector<std::size_t> sweepIndices(std::size_t count) {
  std::vector<std::size_t> out;
  if (!sweepSampled()) {
    for (std::size_t i = 0; i < count; ++i) out.push_back(i);
    return out;
  }
  // FNV-1a of "Suite.Test": a stable offset per test, independent of the
  // standard library's std::hash.
  std::uint64_t hash = 1469598103934665603ull;
  if (const auto* info = ::testing::UnitTest::GetInstance()->current_test_info()) {
    for (const char c : std::string(info->test_suite_name()) + "." + info->name()) {
      hash ^= static_cast<unsigned char>(c);
      hash *= 1099511628211ull;
    }
  }
  for (std::size_t i = hash % kSweepStride; i < count; i += kSweepStride) out.push_back(i);
  if (out.empty() && count > 0) out.push_back(count - 1);
  return out;
}

std::vector<bool> sweepMask(std::size_t count) {
  std::vector<bool> visited(count, false);
  for (std::size_t i : sweepIndices(count)) visited[i] = true;
  return visited;
}

std::vector<std::filesystem::path> bundledSceneFiles() {
  std::vector<std::filesystem::path> out;
  for (const auto& e : std::filesystem::directory_iterator(sourceDir() / "scenes"))
    if (e.path().extension() == ".toml") out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace rollspin::test
