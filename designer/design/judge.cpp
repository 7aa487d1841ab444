#include "designer/design/judge.hpp"

#include "designer/equipment/equipment_registry.hpp"

namespace feedflow {

Verdict judge(const Case& c, const Estimates& estimates) { return equipment_of(c.kind()).judge(c, estimates); }

}  // namespace feedflow
