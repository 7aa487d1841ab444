#include "designer/case/shipped_cases.hpp"

namespace feedflow {

std::filesystem::path shipped_case_root() {
  std::error_code ec;
  if (std::filesystem::is_directory("cases", ec)) return ".";
  return FEEDFLOW_SOURCE_DIR;
}

}  // namespace feedflow
