#pragma once
// exp and log as straight-line arithmetic (no calls, no branches, no table), so that a loop
// over contacts calling them vectorises, with the same result in every lane and in scalar code:
// only IEEE +, -, *, / and integer bit operations, which give the same bits at any vector width
// (in a translation unit without floating-point contraction). glibc's vector math (libmvec) is
// not used because its results differ from its scalar ones and between widths. Both are within
// about 1 ulp of the correctly rounded value over the ranges the contact laws use (tested
// against std::exp and std::log).
#include <bit>
#include <cstdint>

namespace feedflow::lane_math {

namespace detail {
inline constexpr double kRoundMagic = 6755399441055744.0;  // 1.5 x 2^52: adds to round to integer
inline constexpr double kLn2High = 6.93147180369123816490e-01;  // ln 2, upper 32 bits
inline constexpr double kLn2Low = 1.90821492927058770002e-10;   // ln 2 - kLn2High
}  // namespace detail

// e^x for x in [-708, 709] (clamped there: 0 and overflow are not reached). x = n ln2 + r with
// |r| <= ln2 / 2 (Cody-Waite, ln 2 in two parts), e^r by its Taylor series to r^13 (remainder
// below 5e-18), times 2^n built in the exponent bits.
inline double exp(double x) {
  using namespace detail;
  x = x < -708.0 ? -708.0 : (x > 709.0 ? 709.0 : x);
  const double shifted =
      x * 1.4426950408889634 + kRoundMagic;  // n + 1.5 x 2^52, n = rint(x / ln 2)
  const double n = shifted - kRoundMagic;
  const std::int64_t ni =
      std::bit_cast<std::int64_t>(shifted) - std::bit_cast<std::int64_t>(kRoundMagic);
  const double r = (x - n * kLn2High) - n * kLn2Low;
  double p = 1.0 / 6227020800.0;  // 1/13!
  p = p * r + 1.0 / 479001600.0;
  p = p * r + 1.0 / 39916800.0;
  p = p * r + 1.0 / 3628800.0;
  p = p * r + 1.0 / 362880.0;
  p = p * r + 1.0 / 40320.0;
  p = p * r + 1.0 / 5040.0;
  p = p * r + 1.0 / 720.0;
  p = p * r + 1.0 / 120.0;
  p = p * r + 1.0 / 24.0;
  p = p * r + 1.0 / 6.0;
  p = p * r + 0.5;
  p = p * r * r + r;  // e^r - 1
  const double scale = std::bit_cast<double>((ni + 1023) << 52);
  return scale + scale * p;
}

// ln y for finite y > 0 (normal numbers). y = m 2^e with m in [sqrt(1/2), sqrt(2)), ln m =
// 2 atanh(s), s = (m - 1)/(m + 1), |s| < 0.172, by its series to s^21 (remainder below 3e-17
// relative); e ln 2 added in two parts.
inline double log(double y) {
  using namespace detail;
  const std::int64_t bits = std::bit_cast<std::int64_t>(y);
  std::int64_t e = ((bits >> 52) & 0x7ff) - 1023;
  double m = std::bit_cast<double>((bits & 0x000fffffffffffffLL) | 0x3ff0000000000000LL);  // [1, 2)
  const bool high = m > 1.4142135623730951;
  m = high ? 0.5 * m : m;
  e = high ? e + 1 : e;
  const double f = m - 1.0;
  const double s = f / (2.0 + f);
  const double s2 = s * s;
  double p = 1.0 / 21.0;
  p = p * s2 + 1.0 / 19.0;
  p = p * s2 + 1.0 / 17.0;
  p = p * s2 + 1.0 / 15.0;
  p = p * s2 + 1.0 / 13.0;
  p = p * s2 + 1.0 / 11.0;
  p = p * s2 + 1.0 / 9.0;
  p = p * s2 + 1.0 / 7.0;
  p = p * s2 + 1.0 / 5.0;
  p = p * s2 + 1.0 / 3.0;
  // e as a double without an int64 conversion instruction (SSE2 and AVX2 have none).
  const double ed =
      std::bit_cast<double>(e + std::bit_cast<std::int64_t>(kRoundMagic)) - kRoundMagic;
  const double ln_m = 2.0 * s + 2.0 * s * s2 * p;
  return ed * kLn2High + (ln_m + ed * kLn2Low);
}

}  // namespace feedflow::lane_math
