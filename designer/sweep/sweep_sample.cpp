#include "designer/sweep/sweep_sample.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <regex>

#include "models/core/errors.hpp"

namespace feedflow {

SampleRequest parse_sample(const std::string& text) {
  static const std::regex lhs(R"(^\s*lhs:(\d{1,7})(?::(\d{1,19}))?\s*$)");
  std::smatch m;
  if (!std::regex_match(text, m, lhs))
    throw InputError("--sample", text,
                     "expected lhs:N or lhs:N:SEED (a Latin hypercube of N points), e.g. lhs:200");
  SampleRequest s;
  s.points = std::stoul(m[1].str());
  if (s.points < 2 || s.points > 1000000)
    throw InputError("--sample", text, "the number of points must be from 2 to 1 000 000");
  if (m[2].matched) s.seed = std::stoull(m[2].str());
  return s;
}

std::vector<SweepAxis> latin_hypercube(const std::vector<SweepAxis>& axes,
                                       const SampleRequest& sample) {
  const std::size_t n = sample.points;
  std::mt19937_64 random(sample.seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<SweepAxis> sampled;
  for (const SweepAxis& axis : axes) {
    std::vector<std::size_t> stratum(n);
    std::iota(stratum.begin(), stratum.end(), std::size_t{0});
    std::shuffle(stratum.begin(), stratum.end(), random);
    SweepAxis s = axis;
    s.values.clear();
    for (std::size_t p = 0; p < n; ++p) {
      if (axis.span) {
        const double f = (static_cast<double>(stratum[p]) + unit(random)) / static_cast<double>(n);
        const auto& span = *axis.span;
        const double si = span.log ? span.low * std::pow(span.high / span.low, f)
                                   : span.low + f * (span.high - span.low);
        s.values.push_back(axis_value(axis, si, 6));
      } else {  // a list: stratum k of n takes item k * m / n
        s.values.push_back(axis.values[stratum[p] * axis.values.size() / n]);
      }
    }
    sampled.push_back(std::move(s));
  }
  return sampled;
}

}  // namespace feedflow
