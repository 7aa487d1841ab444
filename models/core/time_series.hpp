#pragma once
// A table of quantities sampled over a run (time, discharged mass, kinetic energy, ...), each
// column with its SI unit. A simulation fills it; reports/ writes it as CSV.
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace feedflow {

struct TimeSeriesColumn {
  std::string name;  // "discharged_mass"
  std::string unit;  // "kg"; empty for pure numbers
};

class TimeSeries {
 public:
  TimeSeries() = default;
  explicit TimeSeries(std::vector<TimeSeriesColumn> columns) : columns_(std::move(columns)) {}

  const std::vector<TimeSeriesColumn>& columns() const { return columns_; }
  const std::vector<std::vector<double>>& rows() const { return rows_; }
  bool empty() const { return rows_.empty(); }

  // Appends one sample; throws std::invalid_argument unless it has one value per column.
  void add_row(std::vector<double> row) {
    if (row.size() != columns_.size())
      throw std::invalid_argument("time series row has " + std::to_string(row.size()) +
                                  " values for " + std::to_string(columns_.size()) + " columns");
    rows_.push_back(std::move(row));
  }

 private:
  std::vector<TimeSeriesColumn> columns_;
  std::vector<std::vector<double>> rows_;
};

}  // namespace feedflow
