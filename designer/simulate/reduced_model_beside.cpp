#include "designer/simulate/reduced_model_beside.hpp"

#include "designer/design/design_check.hpp"
#include "reports/result_format.hpp"

namespace feedflow {

void add_reduced_model_results(const Case& c, const std::vector<std::string>& names,
                               DesignRecord& record) {
  const DesignRecord design = design_check(c);
  for (const auto& name : names)
    if (const Estimate* e = find_estimate(design.results, name))
      record.results.emplace_back(reduced_model_key(name), *e);
}

}  // namespace feedflow
