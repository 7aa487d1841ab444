#pragma once
// The record of one design check or simulation: what was asked, with which inputs, what came
// out and the verdict. Every computing command produces one; reports/ writes it as JSON, text
// and (later) PDF.
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "models/core/chart.hpp"
#include "models/core/estimate.hpp"

namespace feedflow {

enum class EquipmentKind { hopper, chute, drum };
const char* to_string(EquipmentKind kind);
EquipmentKind equipment_kind_from_string(const std::string& text);  // throws std::invalid_argument

// One resolved input: dotted key, SI value (or text), SI unit, and how a person reads it.
struct InputValue {
  std::string key;                          // "hopper.semi_angle"
  std::variant<double, std::string, std::vector<double>> value;  // SI number(s) or a label
  std::string si_unit;                      // "rad"; empty for labels and pure numbers
  std::string display;                      // "30 deg"
  std::string source;                       // where the value comes from (materials); may be empty
};

enum class VerdictStatus { pass, marginal, fail, unknown };
const char* to_string(VerdictStatus status);
VerdictStatus verdict_status_from_string(const std::string& text);  // throws std::invalid_argument

// A design record's results: quantity key -> estimate, in order. The same list comes from every
// rung (the reduced models, a DEM or CEL run), and a judge reads it.
using Estimates = std::vector<std::pair<std::string, Estimate>>;

// The estimate of `key`, or null when the list has none.
const Estimate* find_estimate(const Estimates& estimates, std::string_view key);
// Where a time-averaged result keeps the half-width of its mean's 95 % interval, when its band
// is something wider (the drum's angle: 2 SD of the sampled angle): "<key>_interval".
std::string interval_key(std::string_view key);

// One reason of a verdict with the numbers it was judged on: the quantity (a key of the
// record's results), its value and band, and the limit it was held against, all in `unit` (the
// estimate's unit). For a requirement from above (an allowed deposit) `limit` is the largest
// value allowed; from below (a throughput) the least value required. A note does not judge.
struct Finding {
  std::optional<VerdictStatus> status = {};  // pass, marginal or fail; empty for a note
  std::string quantity = {};                 // "critical_outlet_width"; empty when none applies
  std::string text = {};                     // the reason in words, as in Verdict::reasons
  std::optional<double> value = {};
  std::optional<double> low = {};
  std::optional<double> high = {};
  std::optional<double> limit = {};
  std::string unit = {};                     // of value, low, high and limit
  std::string display_unit = {};  // unit people read them in (the estimate's); empty = unit
};

struct Verdict {
  VerdictStatus status = VerdictStatus::unknown;
  std::vector<std::string> reasons;   // every reason in words, "marginal: ..." or a note
  std::vector<Finding> findings = {};  // the reasons a judge gave, with their keys and numbers
};

// How a simulation spent its time: the performance block that ends the run (LAMMPS-style): wall
// time, throughput figures as text with their units, and the time of each phase.
struct PerformanceBlock {
  std::string title;  // "DEM run", "CEL run"
  double wall_seconds = 0.0;
  std::vector<std::pair<std::string, std::string>> figures =
      {};  // "throughput" -> "1.2e6 particle-steps/s"
  std::vector<std::pair<std::string, double>> phases = {};  // "pairs" -> seconds
};

struct DesignRecord {
  std::string feedflow_version;
  std::string case_name;
  EquipmentKind kind = EquipmentKind::hopper;
  std::string case_file;
  std::string description;
  std::vector<InputValue> inputs;
  Estimates results;                  // quantity name -> estimate, in order
  Verdict verdict;
  std::vector<Chart> charts;          // curves for the report
  std::vector<std::string> assumptions;  // what the models assume, and which way each errs
  std::string command_line;           // how the record was produced
  // Folders of the simulations behind the results (their snapshot files give the report its
  // pictures), relative to the folder of the results file.
  std::vector<std::string> simulation_runs = {};
  std::vector<PerformanceBlock> performance = {};  // of the simulations run for this record
  double wall_seconds = 0.0;
};

}  // namespace feedflow
