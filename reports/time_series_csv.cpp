#include "reports/time_series_csv.hpp"

#include <cstdio>

namespace feedflow {

std::string to_csv(const TimeSeries& series) {
  std::string csv;
  const auto& columns = series.columns();
  for (std::size_t i = 0; i < columns.size(); ++i) {
    if (i) csv += ',';
    csv += columns[i].name;
    if (!columns[i].unit.empty()) csv += " [" + columns[i].unit + "]";
  }
  csv += '\n';
  char number[32];
  for (const auto& row : series.rows()) {
    for (std::size_t i = 0; i < row.size(); ++i) {
      if (i) csv += ',';
      std::snprintf(number, sizeof number, "%.17g", row[i]);
      csv += number;
    }
    csv += '\n';
  }
  return csv;
}

}  // namespace feedflow
