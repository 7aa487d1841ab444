#include "models/core/estimate.hpp"

#include <stdexcept>

namespace feedflow {

const char* to_string(Rung rung) {
  switch (rung) {
    case Rung::L0: return "L0";
    case Rung::L1: return "L1";
    case Rung::L2: return "L2";
    case Rung::L3: return "L3";
  }
  return "L0";
}

Rung rung_from_string(const std::string& text) {
  if (text == "L0") return Rung::L0;
  if (text == "L1") return Rung::L1;
  if (text == "L2") return Rung::L2;
  if (text == "L3") return Rung::L3;
  throw std::invalid_argument("rung must be L0, L1, L2 or L3, got \"" + text + "\"");
}

}  // namespace feedflow
