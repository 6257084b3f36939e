// Small text helpers shared across modules (ASCII only: file extensions,
// container tag keys, font names; the nearest name for "did you mean").
#pragma once

#include <cctype>
#include <string>
#include <vector>

namespace rollspin {

// `text` with ASCII letters in lower case (locale-independent).
inline std::string asciiLowercase(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

// Edit distance (insertions, deletions, substitutions, adjacent swaps).
[[nodiscard]] std::size_t editDistance(const std::string& a, const std::string& b);

// The candidate nearest to `typed` when it is close enough to be a typo
// (at most a third of its length, and at least 1, edits away), else "".
[[nodiscard]] std::string nearestName(const std::string& typed, const std::vector<std::string>& candidates);

}  // namespace rollspin
