#include "core/did_you_mean.hpp"

#include <algorithm>
#include <cstdlib>
#include <vector>

namespace si {

int edit_distance(const std::string& a, const std::string& b) {
  // Three rows of the dynamic-programming table: the transposition looks two rows back.
  const size_t m = b.size();
  std::vector<int> before(m + 1), last(m + 1), row(m + 1);
  for (size_t j = 0; j <= m; ++j) last[j] = static_cast<int>(j);
  for (size_t i = 1; i <= a.size(); ++i) {
    row[0] = static_cast<int>(i);
    for (size_t j = 1; j <= m; ++j) {
      const int substitute = last[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      row[j] = std::min({last[j] + 1, row[j - 1] + 1, substitute});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        row[j] = std::min(row[j], before[j - 2] + 1);
    }
    before.swap(last);
    last.swap(row);
  }
  return last[m];
}

std::string did_you_mean(const std::string& word, const std::vector<std::string>& candidates) {
  const int tolerance = std::max(1, static_cast<int>(word.size()) / 3);
  const std::string* best = nullptr;
  int best_distance = tolerance + 1;
  for (const auto& c : candidates) {
    // The distance is at least the difference in length: skip the quadratic table for words
    // that cannot be close (a megabyte-long value must not take seconds here).
    const auto gap = static_cast<long>(word.size()) - static_cast<long>(c.size());
    if (std::abs(gap) > tolerance) continue;
    const int d = edit_distance(word, c);
    if (d < best_distance) {
      best_distance = d;
      best = &c;
    }
  }
  return best ? " (did you mean '" + *best + "'?)" : "";
}

}  // namespace si
