#pragma once
// The unit each quantity of a case file was written in ("design.required_throughput" -> "t/h",
// "hopper.outlet_width" -> "mm"), --set overrides included, so inputs and results can be shown
// the way the engineer wrote them. Numbers without a unit (SI) are not listed.
#include <map>
#include <string>
#include <toml++/toml.h>

namespace feedflow {

// Dotted key -> unit text as written, over every table of the case (value records
// `{ value = "5 t/h", source = ... }` under their own key).
std::map<std::string, std::string> written_units(const toml::table& root);

// The unit part of a quantity's text ("5 t/h" -> "t/h", "32deg" -> "deg"); empty when the text
// is a bare number or not a quantity.
std::string unit_written(const std::string& text);

}  // namespace feedflow
