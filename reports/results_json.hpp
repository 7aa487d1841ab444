#pragma once
// The results JSON, the machine-readable record every computing command writes. Its shape is
// stable (README, "Results JSON"):
//   {"feedflow": version,
//    "case": {"name", "kind", "file", "description"},
//    "inputs": {nested by dotted key, SI numbers or labels},
//    "input_units": {dotted key: SI unit}, "input_sources": {dotted key: source},
//    "results": {quantity: {"value", "unit", "low", "high", "model", "rung", "display_unit"}},
//    "verdict": {"status", "reasons",
//                "findings": [{"status" (pass|marginal|fail|note), "quantity", "text", "value",
//                "low",
//                              "high", "limit", "unit", "display_unit"}] (when a judge made the
//                              verdict; numbers or null, in "unit", the quantity's result unit)},
//    "charts": [{"id", "title", "x": axis, "y": axis, "series": [...], "note"}],
//    "assumptions": [...], "provenance": {"command_line", "simulation_runs"},
//    "timing": {"wall_s"},
//    "performance": [{"title", "wall_s", "figures": {name: text}, "phases_s": {name: s}}]
//    (simulations)}
#include <nlohmann/json.hpp>

#include "models/core/design_record.hpp"

namespace feedflow {

nlohmann::ordered_json to_json(const DesignRecord& record);

// Reads a results JSON back; throws std::invalid_argument naming the offending field.
DesignRecord design_record_from_json(const nlohmann::ordered_json& json);
// Its "results" object alone, in order (a run's results read back by bench and verify).
Estimates estimates_from_json(const nlohmann::ordered_json& results);

}  // namespace feedflow
