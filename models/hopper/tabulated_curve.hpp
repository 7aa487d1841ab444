#pragma once
// A measured curve y(x) given as points, read piecewise linearly (flow functions, density
// tables). Outside the points it either extends the end segments or holds the end values.
#include <vector>

namespace feedflow {

class TabulatedCurve {
 public:
  enum class Beyond { extend_end_segments, hold_end_values };
  // x strictly increasing, at least 2 points, all finite; throws std::invalid_argument.
  TabulatedCurve(std::vector<double> x, std::vector<double> y, Beyond beyond);

  double operator()(double x) const;
  const std::vector<double>& x() const { return x_; }
  const std::vector<double>& y() const { return y_; }
  bool covers(double x) const { return x >= x_.front() && x <= x_.back(); }

 private:
  std::vector<double> x_, y_;
  Beyond beyond_;
};

}  // namespace feedflow
