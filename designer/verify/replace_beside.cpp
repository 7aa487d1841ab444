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

}  // namespace feedflow
