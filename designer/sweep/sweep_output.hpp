#pragma once
// What a sweep writes: sweep.json (the sweep's keys, values and every point with its inputs,
// verdict, governing checks and results, each number with its unit), sweep.csv (one row per
// point, a column per input and per result's value, low and high, the unit in each header) and
// the text a person reads (the verdicts counted, the first points listed).
#include <string>
#include <vector>

#include "designer/sweep/sweep_grid.hpp"

namespace feedflow {

struct SweepTiming {
  double wall_seconds = 0.0;   // the whole command up to writing its files
  double point_seconds = 0.0;  // answering the points (points/s is taken over this)
  int threads = 1;
  int ranks = 1;                        // simulated points: the MPI ranks sharing them
  std::size_t made = 0, read_back = 0;  // simulated points run now, and read back
};

std::string sweep_json(const SweepRequest& request, const std::vector<SweepPoint>& points,
                       const SweepTiming& timing, const std::string& command_line);
std::string sweep_csv(const SweepRequest& request, const std::vector<SweepPoint>& points);
// `rows`: how many points the text lists (the rest are counted).
std::string sweep_summary(const SweepRequest& request, const std::vector<SweepPoint>& points,
                          const SweepTiming& timing, std::size_t rows = 20);

}  // namespace feedflow
