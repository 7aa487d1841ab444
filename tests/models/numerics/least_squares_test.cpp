// Nonlinear least squares (models/numerics/least_squares): exact data give back the parameters
// that made them, noisy data give standard errors that cover the truth, and bad calls throw.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "models/core/errors.hpp"
#include "models/numerics/least_squares.hpp"

namespace feedflow {
namespace {

// y = a exp(-b x) + c on 20 points.
std::vector<double> decay(double a, double b, double c, double noise, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> n(0.0, noise);
  std::vector<double> y;
  for (int i = 0; i < 20; ++i) y.push_back(a * std::exp(-b * 0.25 * i) + c + (noise > 0 ? n(rng) : 0.0));
  return y;
}

auto residuals_of(const std::vector<double>& y) {
  return [y](std::span<const double> p, std::span<double> r) {
    for (std::size_t i = 0; i < y.size(); ++i) r[i] = p[0] * std::exp(-p[1] * 0.25 * i) + p[2] - y[i];
  };
}

// Data made by the model itself are fitted back to the parameters that made them.
TEST(LeastSquares, ExactDataGiveBackTheirParameters) {
  const auto y = decay(5.0, 1.5, 1.0, 0.0, 1);
  const LeastSquaresFit fit = least_squares(residuals_of(y), {1.0, 1.0, 0.0}, y.size());
  EXPECT_NEAR(fit.parameters[0], 5.0, 1e-8);
  EXPECT_NEAR(fit.parameters[1], 1.5, 1e-8);
  EXPECT_NEAR(fit.parameters[2], 1.0, 1e-8);
  EXPECT_LT(fit.rms, 1e-9);
}

// With noise of 0.05 the truth lies within three standard errors of each fitted parameter.
TEST(LeastSquares, StandardErrorsCoverTheTruthUnderNoise) {
  const auto y = decay(5.0, 1.5, 1.0, 0.05, 7);
  const LeastSquaresFit fit = least_squares(residuals_of(y), {1.0, 1.0, 0.0}, y.size());
  const double truth[] = {5.0, 1.5, 1.0};
  for (int k = 0; k < 3; ++k) {
    EXPECT_GT(fit.standard_errors[k], 0.0);
    EXPECT_LT(std::abs(fit.parameters[k] - truth[k]), 3.0 * fit.standard_errors[k]) << k;
  }
  EXPECT_NEAR(fit.rms, 0.05, 0.03);
}

// Fewer residuals than parameters, no parameters, or residuals that are not numbers: no fit.
TEST(LeastSquares, RefusesWhatItCannotFit) {
  const auto y = decay(5.0, 1.5, 1.0, 0.0, 1);
  EXPECT_THROW(least_squares(residuals_of(y), {1.0, 1.0, 0.0}, 2), std::invalid_argument);
  EXPECT_THROW(least_squares(residuals_of(y), {}, y.size()), std::invalid_argument);
  const auto nan = [](std::span<const double>, std::span<double> r) {
    for (double& x : r) x = NAN;
  };
  EXPECT_THROW(least_squares(nan, {1.0}, 3), NumericalFailure);
}

}  // namespace
}  // namespace feedflow
