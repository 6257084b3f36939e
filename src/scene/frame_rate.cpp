#include "scene/frame_rate.hpp"

#include <fmt/format.h>

#include <charconv>
#include <climits>
#include <cmath>
#include <numeric>

namespace rollspin::scene {

namespace {

std::optional<FrameRate> reduced(long long num, long long den) {
  if (num <= 0 || den <= 0) return std::nullopt;
  const long long g = std::gcd(num, den);
  num /= g;
  den /= g;
  // libavcodec's time base and frame rate are int rationals.
  if (num > INT_MAX || den > INT_MAX) return std::nullopt;
  return FrameRate{num, den};
}

}  // namespace

std::string FrameRate::text() const { return den == 1 ? std::to_string(num) : fmt::format("{}/{}", num, den); }

std::string FrameRate::describe() const { return den == 1 ? text() : fmt::format("{} ({:.6g})", text(), value()); }

std::optional<FrameRate> frameRateFromDecimal(double value) {
  if (!std::isfinite(value) || value <= 0.0 || value > 1e6) return std::nullopt;
  if (value == std::round(value)) return reduced(static_cast<long long>(value), 1);
  // NTSC: N·1000/1001 written to two or three places (23.976 or 23.98,
  // 29.97, 59.94, 119.88): within 0.005 of the exact rate. An integer N is
  // 0.001·N away from its NTSC neighbour, so only non-integers get here.
  const double n = std::round(value * 1.001);
  if (n >= 1.0 && std::abs(value - n * 1000.0 / 1001.0) <= 0.005)
    return reduced(static_cast<long long>(n) * 1000, 1001);
  // Any other decimal exactly, if it has at most three places.
  const double milli = std::round(value * 1000.0);
  if (std::abs(value * 1000.0 - milli) > 1e-6 * milli) return std::nullopt;
  return reduced(static_cast<long long>(milli), 1000);
}

std::optional<FrameRate> frameRateFromText(std::string_view text) {
  const auto slash = text.find('/');
  if (slash == std::string_view::npos) {
    double value = 0.0;
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || ec != std::errc() || ptr != text.data() + text.size()) return std::nullopt;
    return frameRateFromDecimal(value);
  }
  auto whole = [](std::string_view part, long long& out) {
    if (part.empty() || part.size() > 12) return false;
    for (char c : part)
      if (c < '0' || c > '9') return false;
    const auto [ptr, ec] = std::from_chars(part.data(), part.data() + part.size(), out);
    return ec == std::errc() && ptr == part.data() + part.size();
  };
  long long num = 0, den = 0;
  if (!whole(text.substr(0, slash), num) || !whole(text.substr(slash + 1), den)) return std::nullopt;
  return reduced(num, den);
}

}  // namespace rollspin::scene
