#include "core/text.hpp"

#include <algorithm>

namespace rollspin {

std::size_t editDistance(const std::string& a, const std::string& b) {
  // Optimal string alignment distance: a swapped pair of letters is one edit.
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i)
    for (std::size_t j = 1; j <= b.size(); ++j) {
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

std::string nearestName(const std::string& typed, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t bestDistance = 0;
  for (const std::string& c : candidates) {
    const std::size_t dist = editDistance(typed, c);
    if (best.empty() || dist < bestDistance) {
      best = c;
      bestDistance = dist;
    }
  }
  const std::size_t allowed = std::max<std::size_t>(1, typed.size() / 3);
  return !best.empty() && bestDistance > 0 && bestDistance <= allowed ? best : "";
}

}  // namespace rollspin
