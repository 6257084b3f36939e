// Small text helpers shared across modules (ASCII only: file extensions,
// container tag keys, font names).
#pragma once

#include <cctype>
#include <string>

namespace rollspin {

// `text` with ASCII letters in lower case (locale-independent).
inline std::string asciiLowercase(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

}  // namespace rollspin
