#pragma once
// Definite integrals by GSL's adaptive quadrature, with GSL errors turned into NumericalFailure.
#include <functional>
#include <string>

namespace feedflow {

// Integral of f over [a, b] by GSL's QAGS (adaptive, tolerates integrable end singularities),
// to abs_tol or rel_tol, whichever is looser (an integral near zero needs abs_tol). Throws
// NumericalFailure "<what>: quadrature failed (...)" when GSL fails or the result is not finite.
double adaptive_integral(const std::function<double(double)>& f, double a, double b, double abs_tol,
                         double rel_tol, const std::string& what);

}  // namespace feedflow
