#include "designer/verify/replace_beside.hpp"

#include <algorithm>

#include "reports/result_format.hpp"

namespace feedflow {

void replace_beside(Estimates& results, const std::string& key, Estimate rung) {
  const auto it =
      std::find_if(results.begin(), results.end(), [&](const auto& r) { return r.first == key; });
  if (it == results.end()) {
    results.emplace_back(key, std::move(rung));
    return;
  }
  Estimate reduced = it->second;
  rung.display_unit = reduced.display_unit;
  it->second = std::move(rung);
  results.emplace(it + 1, reduced_model_key(key), std::move(reduced));
}

Estimate particle_bracket(double stops_at, double flows_at, std::string model) {
  Estimate e;
  e.value = 0.5 * (stops_at + flows_at);  // SI, as the reduced value and the judge read it
  e.low = stops_at;
  e.high = flows_at;
  e.unit = "m";
  e.display_unit = "mm";
  e.model = std::move(model);
  e.rung = Rung::L3;
  return e;
}

}  // namespace feedflow
