#include "models/numerics/mser_truncation.hpp"

#include <algorithm>
#include <limits>

namespace feedflow {

std::pair<std::size_t, std::size_t> mser_truncation(const std::vector<double>& x,
                                                    std::size_t min_kept, MserEnds ends) {
  const std::size_t n = x.size();
  std::vector<double> s1(n + 1, 0.0), s2(n + 1, 0.0);  // prefix sums keep it O(n^2)
  const double shift = x.empty() ? 0.0 : x[n / 2];     // for round-off in the sums of squares
  for (std::size_t k = 0; k < n; ++k) {
    s1[k + 1] = s1[k] + (x[k] - shift);
    s2[k + 1] = s2[k] + (x[k] - shift) * (x[k] - shift);
  }
  const std::size_t kept_at_least = std::max<std::size_t>(min_kept, 2);
  const std::size_t most_back = ends == MserEnds::both ? n / 2 : 0;
  std::pair<std::size_t, std::size_t> best{0, 0};
  double best_score = std::numeric_limits<double>::infinity();
  for (std::size_t front = 0; front <= n / 2; ++front)
    for (std::size_t back = 0; back <= most_back && front + back + kept_at_least <= n; ++back) {
      const std::size_t a = front, b = n - back;
      const double m = static_cast<double>(b - a);
      const double mean = (s1[b] - s1[a]) / m;
      const double var = std::max(0.0, (s2[b] - s2[a]) / m - mean * mean) * m / (m - 1.0);
      const double score = var / (m * m);
      if (score < best_score) {
        best_score = score;
        best = {front, back};
      }
    }
  return best;
}

}  // namespace feedflow
