// FrameRate — frames per second as an exact rational num/den (reduced):
// an integer n (n/1), an NTSC rate given as a decimal (23.976, 29.97, 59.94,
// … = N·1000/1001), another decimal of at most 3 places (12.5 = 25/2), or a
// string "num/den" ("30000/1001"). Frame k starts at exactly k·den/num s, so
// a 29.97 fps clip's timestamps and frame count use 30000/1001, never a
// rounded 29.97.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace rollspin::scene {

struct FrameRate {
  long long num = 30, den = 1;
  [[nodiscard]] double value() const { return double(num) / double(den); }
  // "30", or "30000/1001" (what the scene printer writes back).
  [[nodiscard]] std::string text() const;
  // For messages: "30", or "30000/1001 (29.97)".
  [[nodiscard]] std::string describe() const;
  friend bool operator==(const FrameRate&, const FrameRate&) = default;
};

// Both return nullopt for a value that is none of the forms above or does
// not fit the encoder's 32-bit rationals; the range check is the caller's.
[[nodiscard]] std::optional<FrameRate> frameRateFromDecimal(double value);
// "num/den" with positive integers, or a decimal as above.
[[nodiscard]] std::optional<FrameRate> frameRateFromText(std::string_view text);

}  // namespace rollspin::scene
