#pragma once
// Particle snapshots of a DEM run: one HDF5 file per run with a group per snapshot
// (/snapshots/step_<step>: time [s] and step attributes; position, velocity, angular_velocity,
// radius, id, layer datasets with their units) and an XDMF sidecar beside it (same stem,
// .xdmf) listing every snapshot as a temporal collection, so ParaView opens the run. The HDF5
// file is closed (flushed) after each snapshot and the sidecar rewritten whole, so a run
// stopped at any moment leaves both readable.
//
//   ParticleSnapshots snapshots("out/particles.h5", 200);   // every 200 steps
//   for (...) { engine.run_steps(1); snapshots.write_if_due(engine.particles(), engine.time(), engine.step()); }
#include <filesystem>
#include <string>
#include <vector>

#include "fullsim/common/scene_outline.hpp"
#include "fullsim/common/xdmf_point_series.hpp"
#include "fullsim/dem/particle_store.hpp"

namespace feedflow {

class ParticleSnapshots {
 public:
  // The first snapshot creates (truncates) `hdf5_file` and its sidecar; `every_steps` > 0 is
  // the interval of write_if_due().
  ParticleSnapshots(std::filesystem::path hdf5_file, long every_steps);

  // Writes a snapshot now; returns its group. The first one also writes the scene's outline
  // (scene_outline.hpp), when given.
  std::string write(const ParticleStore& particles, double time, long step,
                    const SceneOutline* outline = nullptr);
  // Writes one when `step` is a multiple of the interval (and not already written).
  bool write_if_due(const ParticleStore& particles, double time, long step);

  const std::filesystem::path& hdf5_path() const { return hdf5_; }
  const std::filesystem::path& xdmf_path() const { return series_.path(); }
  std::size_t count() const { return series_.clouds().size(); }
  static std::string group_name(long step);

 private:
  std::filesystem::path hdf5_;
  long every_;
  long last_step_ = -1;
  XdmfPointSeries series_;
};

// One snapshot read back (tests, post-processing).
struct ParticleSnapshot {
  double time = 0.0;
  long step = 0;
  std::vector<Vec3> position, velocity, angular_velocity;
  std::vector<double> radius, layer;
  std::vector<std::uint32_t> id;
};
ParticleSnapshot read_particle_snapshot(const std::filesystem::path& hdf5_file,
                                        const std::string& group);

}  // namespace feedflow
