#include "models/core/chart.hpp"

#include <stdexcept>

namespace feedflow {

const char* to_string(SeriesStyle style) {
  switch (style) {
    case SeriesStyle::line: return "line";
    case SeriesStyle::dashed: return "dashed";
    case SeriesStyle::points: return "points";
    case SeriesStyle::band: return "band";
    case SeriesStyle::marker: return "marker";
  }
  return "line";
}

SeriesStyle series_style_from_string(const std::string& text) {
  for (auto s : {SeriesStyle::line, SeriesStyle::dashed, SeriesStyle::points, SeriesStyle::band,
                 SeriesStyle::marker})
    if (text == to_string(s)) return s;
  throw std::invalid_argument("series style must be line, dashed, points, band or marker, got \"" +
                              text + "\"");
}

}  // namespace feedflow
