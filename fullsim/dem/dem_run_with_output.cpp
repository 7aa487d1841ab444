#include "fullsim/dem/dem_run_with_output.hpp"

#include <algorithm>
#include <iostream>

#include "models/os/interrupt_request.hpp"

namespace feedflow {

DemRunEnd run_dem_with_output(DemEngine& engine, long steps, const DemRunOutput& output) {
  engine.prepare(std::cout);
  const long end = engine.step() + steps;
  if (output.snapshots)
    output.snapshots->write_if_due(engine.particles(), engine.time(), engine.step());
  while (engine.step() < end) {
    if (interrupt_requested()) {
      if (!output.checkpoint.empty()) engine.write_checkpoint(output.checkpoint);
      return DemRunEnd::interrupted;
    }
    engine.run_steps(1);
    if (output.snapshots)
      output.snapshots->write_if_due(engine.particles(), engine.time(), engine.step());
  }
  if (!output.checkpoint.empty()) engine.write_checkpoint(output.checkpoint);
  return DemRunEnd::completed;
}

}  // namespace feedflow
