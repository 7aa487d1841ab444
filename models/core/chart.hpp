#pragma once
// A chart as data: the curves a design check computes for a report (B_c against semi-angle,
// discharge against outlet width, stress profiles, ...). Plain numbers in the axis units, so a
// results JSON can be re-plotted without re-running anything. reports/ draws it.
#include <string>
#include <vector>

namespace feedflow {

struct ChartAxis {
  std::string label;  // "semi-angle"
  std::string unit;   // "deg"; empty for pure numbers
  bool logarithmic = false;
};

enum class SeriesStyle { line, dashed, points, band, marker };
const char* to_string(SeriesStyle style);
SeriesStyle series_style_from_string(const std::string& text);  // throws std::invalid_argument

struct ChartSeries {
  std::string label;            // legend text
  SeriesStyle style = SeriesStyle::line;
  std::vector<double> x;        // in the x axis unit
  std::vector<double> y;        // in the y axis unit; for a band, the lower edge
  std::vector<double> y_upper;  // band only: the upper edge
  int colour = -1;              // palette index; -1: by position (a band and its line may share one)
};

struct Chart {
  std::string id;     // file-name friendly: "critical_outlet_width_vs_semi_angle"
  std::string title;  // "Critical outlet width against semi-angle"
  ChartAxis x;
  ChartAxis y;
  std::vector<ChartSeries> series;
  std::string note;   // one line under the chart: what it shows, which way it errs
};

}  // namespace feedflow
