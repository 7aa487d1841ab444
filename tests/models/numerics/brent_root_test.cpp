// The shared GSL wrappers: Brent's method and adaptive quadrature report failures as a status or
// a NumericalFailure naming the computation, never by aborting the program.
#include <gtest/gtest.h>
#include <gsl/gsl_errno.h>

#include <cmath>
#include <limits>
#include <string>

#include "models/core/errors.hpp"
#include "models/numerics/adaptive_integral.hpp"
#include "models/numerics/brent_root.hpp"

namespace feedflow {
namespace {

// The root of x^2 - 2 in [0, 2] is sqrt(2), to the relative tolerance asked for.
TEST(BrentRoot, FindsTheBracketedRootToTheTolerance) {
  const BrentSearch s = brent_search([](double x) { return x * x - 2.0; }, 0.0, 2.0, {0.0, 1e-12});
  ASSERT_TRUE(s.converged());
  EXPECT_NEAR(s.root, std::sqrt(2.0), 2e-12);
  EXPECT_NEAR(brent_root([](double x) { return std::cos(x); }, 0.0, 3.0, 1e-14, 0.0, "cos"),
              std::acos(0.0), 1e-13);
}

// An interval that brackets no sign change, a function that is not finite and too few
// iterations each come back as GSL's status; brent_root throws with the computation's name.
TEST(BrentRoot, FailuresAreStatusesAndNamedErrors) {
  const auto square = [](double x) { return x * x + 1.0; };
  EXPECT_EQ(brent_search(square, 0.0, 2.0, {0.0, 1e-12}).status, GSL_EINVAL);
  const auto broken = [](double x) {
    return x > 1.5 ? std::numeric_limits<double>::quiet_NaN() : x - 1.0;
  };
  EXPECT_EQ(brent_search(broken, 0.0, 2.0, {0.0, 1e-12}).status, GSL_EBADFUNC);
  const auto slow = brent_search([](double x) { return x * x - 2.0; }, 0.0, 2.0, {0.0, 1e-15, 2});
  EXPECT_EQ(slow.status, GSL_CONTINUE);
  EXPECT_FALSE(slow.converged());
  try {
    brent_root(square, 0.0, 2.0, 0.0, 1e-12, "test root");
    FAIL() << "no root, no throw";
  } catch (const NumericalFailure& e) {
    EXPECT_EQ(
        std::string(e.what()).rfind("test root: Brent's method did not converge on [0.000000, "
                                    "2.000000] (",
                                    0),
        0u)
        << e.what();
  }
}

// QAGS integrates an integrable end singularity (1/sqrt(x) on [0, 1] is 2) and refuses a
// divergent integral (1/x) with a NumericalFailure.
TEST(AdaptiveIntegral, IntegrableSingularityAndDivergence) {
  EXPECT_NEAR(adaptive_integral([](double x) { return 1.0 / std::sqrt(x); }, 0.0, 1.0, 0.0, 1e-10,
                                "1/sqrt(x)"),
              2.0, 1e-9);
  EXPECT_THROW(adaptive_integral([](double x) { return 1.0 / x; }, 0.0, 1.0, 0.0, 1e-10, "1/x"),
               NumericalFailure);
}

}  // namespace
}  // namespace feedflow
