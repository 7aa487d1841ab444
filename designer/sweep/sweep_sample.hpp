#pragma once
// `--sample lhs:N[:SEED]`: a Latin hypercube of N points over the --vary axes instead of their
// grid. A range (A..B) is cut into N strata of equal width (equal ratio for a log range) and
// each point takes a random value in its own stratum; a list's items are spread over the N
// points as evenly as N allows. The strata are shuffled independently per axis with a seeded
// generator, so a sample is the same on every machine and run.
#include <cstdint>
#include <string>
#include <vector>

#include "designer/sweep/sweep_axis.hpp"

namespace feedflow {

struct SampleRequest {
  std::size_t points = 0;
  std::uint64_t seed = 1;
};

// Parses the text after --sample ("lhs:200", "lhs:200:7"); InputError naming --sample.
SampleRequest parse_sample(const std::string& text);

// The axes with N values each (value n of every axis is point n).
std::vector<SweepAxis> latin_hypercube(const std::vector<SweepAxis>& axes,
                                       const SampleRequest& sample);

}  // namespace feedflow
