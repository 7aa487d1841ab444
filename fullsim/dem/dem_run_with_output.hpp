#pragma once
// A DEM run with its outputs: particle snapshots at their interval and, when an interrupt is
// requested (Ctrl-C, see interrupt_request.hpp), a checkpoint written before it returns.
//
//   install_interrupt_handler();
//   ParticleSnapshots snapshots(out / "particles.h5", 500);
//   if (run_dem_with_output(engine, steps, {&snapshots, out / "checkpoint.h5"}) == DemRunEnd::interrupted) ...
#include <filesystem>

#include "fullsim/dem/dem_engine.hpp"
#include "fullsim/dem/particle_snapshots.hpp"

namespace feedflow {

struct DemRunOutput {
  ParticleSnapshots* snapshots = nullptr;    // none: no snapshots
  std::filesystem::path checkpoint;          // written on an interrupt (and at the end if set)
};

enum class DemRunEnd { completed, interrupted };

// Runs `steps` steps (prepares the engine first if needed). The interrupt flag is checked
// between steps; on an interrupt the checkpoint is written and the run returns early.
DemRunEnd run_dem_with_output(DemEngine& engine, long steps, const DemRunOutput& output);

}  // namespace feedflow
