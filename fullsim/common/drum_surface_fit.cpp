#include "fullsim/common/drum_surface_fit.hpp"

#include <gsl/gsl_fit.h>
#include <gsl/gsl_multifit.h>

#include <algorithm>
#include <cmath>

namespace feedflow {

namespace {

// Least-squares polynomial of `degree` through the points (GSL); coefficients c0, c1, ...
std::vector<double> fit_polynomial(const std::vector<SurfacePoint>& pts, std::size_t degree) {
  const std::size_t n = pts.size(), m = degree + 1;
  gsl_matrix* a = gsl_matrix_alloc(n, m);
  gsl_vector* y = gsl_vector_alloc(n);
  gsl_vector* c = gsl_vector_alloc(m);
  gsl_matrix* cov = gsl_matrix_alloc(m, m);
  gsl_multifit_linear_workspace* w = gsl_multifit_linear_alloc(n, m);
  for (std::size_t i = 0; i < n; ++i) {
    double power = 1.0;
    for (std::size_t j = 0; j < m; ++j, power *= pts[i].x) gsl_matrix_set(a, i, j, power);
    gsl_vector_set(y, i, pts[i].z);
  }
  double chi2 = 0.0;
  gsl_multifit_linear(a, y, c, cov, &chi2, w);
  std::vector<double> out(m);
  for (std::size_t j = 0; j < m; ++j) out[j] = gsl_vector_get(c, j);
  gsl_multifit_linear_free(w);
  gsl_matrix_free(cov);
  gsl_vector_free(c);
  gsl_vector_free(y);
  gsl_matrix_free(a);
  return out;
}

}  // namespace

DrumSurfaceFit fit_drum_surface(const std::vector<SurfacePoint>& surface, double drum_radius,
                                double central_fraction) {
  DrumSurfaceFit fit;
  if (surface.size() < 4) return fit;
  const auto [lo, hi] = std::minmax_element(surface.begin(), surface.end(),
                                            [](const auto& a, const auto& b) { return a.x < b.x; });
  fit.chord_low = lo->x;
  fit.chord_high = hi->x;
  const double mid = 0.5 * (fit.chord_low + fit.chord_high);
  const double half = 0.5 * central_fraction * (fit.chord_high - fit.chord_low);
  std::vector<double> xs, zs;
  for (const auto& p : surface)
    if (std::abs(p.x - mid) <= half) {
      xs.push_back(p.x);
      zs.push_back(p.z);
    }
  fit.points = xs.size();
  if (xs.size() < 4) return fit;
  double c0 = 0, c1 = 0, cov00 = 0, cov01 = 0, cov11 = 0, sumsq = 0;
  gsl_fit_linear(xs.data(), 1, zs.data(), 1, xs.size(), &c0, &c1, &cov00, &cov01, &cov11, &sumsq);
  fit.valid = true;
  fit.slope_angle = std::atan(c1);
  fit.intercept = c0;
  // The shape over the inner 80 % of the chord (the last columns touch the shell).
  const double shape_half = 0.4 * (fit.chord_high - fit.chord_low);
  std::vector<SurfacePoint> inner;
  for (const auto& p : surface)
    if (std::abs(p.x - mid) <= shape_half) inner.push_back(p);
  if (inner.size() >= 8) {
    const auto c = fit_polynomial(inner, 3);
    for (int k = 0; k <= 40; ++k) {
      const double x = mid - shape_half + 2.0 * shape_half * k / 40.0;
      const double cubic = c[0] + x * (c[1] + x * (c[2] + x * c[3]));
      fit.bulge = std::max(fit.bulge, std::abs(cubic - (c0 + c1 * x)) / drum_radius);
    }
  }
  return fit;
}

}  // namespace feedflow
