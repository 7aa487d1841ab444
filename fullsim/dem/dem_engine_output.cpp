// A DEM engine's output and restart: its checkpoint (gathered from the ranks of a shared run,
// written by the first), its particle snapshots, and restoring a checkpoint into it.
#include <optional>
#include <stdexcept>

#include "fullsim/dem/dem_engine.hpp"
#include "fullsim/dem/particle_snapshots.hpp"
#include "fullsim/dem/ranks/gathered_checkpoint.hpp"
#include "fullsim/dem/ranks/gathered_particles.hpp"

namespace feedflow {

DemCheckpoint DemEngine::checkpoint() const {
  if (!prepared_)
    throw std::logic_error("DemEngine::checkpoint() before prepare(): nothing to continue yet");
  if (rebuild_due_)
    throw std::logic_error("DemEngine::checkpoint() right after inserting or removing particles: "
                           "run a step first");
  DemCheckpoint c;
  c.step = step_;
  c.time = time_;
  c.time_step = time_step_.value;
  c.particle_steps = particle_steps_;
  c.contact_law = kernel_->name();
  c.gravity = settings_.gravity;
  c.box = box_;
  c.particles = particles_;
  c.neighbours = neighbours_;
  c.walls = walls_;
  c.sink = sink_;
  c.guard_initial_energy = guard_.initial_energy();
  c.guard_energy_floor = guard_.energy_floor();
  c.guard_gravity_work = guard_.gravity_work();
  c.guard_wall_speed = guard_.wall_speed();
  if (distributed()) return gather_checkpoint(std::move(c), owned_count(), settings_.ranks);
  return c;
}

void DemEngine::write_checkpoint(const std::filesystem::path& path) const {
  const DemCheckpoint c = checkpoint();
  if (!shared()) {
    write_dem_checkpoint(path, c);
    return;
  }
  // The first rank writes the gathered checkpoint; a failure there stops every rank.
  std::optional<std::string> failure;
  if (settings_.ranks.rank() == 0) try {
      write_dem_checkpoint(path, c);
    } catch (const std::runtime_error& e) {
      failure = e.what();
    }
  if (auto agreed = settings_.ranks.agree_on_failure(failure)) throw std::runtime_error(*agreed);
}

namespace {

// The particle snapshots of an engine (DemEngine::snapshot_writer). A run shared among ranks
// gathers its particles to the first rank, which writes them; a failure there stops every rank.
class ParticleSnapshotWriter final : public SnapshotWriter {
 public:
  ParticleSnapshotWriter(const DemEngine& engine, std::filesystem::path file,
                         const DemRanks& ranks)
      : engine_(engine), ranks_(ranks), snapshots_(std::move(file), 1) {}
  void write() override {
    if (engine_.step() == last_step_) return;
    last_step_ = engine_.step();
    if (ranks_.size() == 1) {
      snapshots_.write(engine_.particles(), engine_.time(), engine_.step(), &engine_.outline());
      ++count_;
      return;
    }
    const ParticleStore all =
        gather_particles(engine_.particles(), engine_.owned_count(), ranks_);
    std::optional<std::string> failure;
    if (ranks_.rank() == 0) try {
        snapshots_.write(all, engine_.time(), engine_.step(), &engine_.outline());
      } catch (const std::runtime_error& e) {
        failure = e.what();
      }
    if (auto agreed = ranks_.agree_on_failure(failure)) throw std::runtime_error(*agreed);
    ++count_;
  }
  std::size_t count() const override { return count_; }
  std::vector<std::filesystem::path> files() const override {
    if (count() == 0) return {};
    return {snapshots_.hdf5_path(), snapshots_.xdmf_path()};
  }

 private:
  const DemEngine& engine_;
  DemRanks ranks_;
  ParticleSnapshots snapshots_;
  long last_step_ = -1;
  std::size_t count_ = 0;
};

}  // namespace

std::unique_ptr<SnapshotWriter> DemEngine::snapshot_writer(const std::filesystem::path& folder,
                                                           bool continuing) const {
  const std::string name =
      continuing ? "particles_from_step_" + std::to_string(step_) + ".h5" : "particles.h5";
  return std::make_unique<ParticleSnapshotWriter>(*this, folder / name, settings_.ranks);
}

// Shared among ranks every rank writes the gathered checkpoint: into the scene's file on the
// first, into one in memory on the others (scene_run.hpp).
void DemEngine::write_checkpoint(Hdf5File& file) const { write_dem_checkpoint(file, checkpoint()); }

void DemEngine::restore(const Hdf5File& file) {
  std::vector<MeshWall> meshes = std::move(meshes_);
  SceneOutline outline = std::move(outline_);
  const Vec3 linear = linear_free_, angular = angular_free_;  // the plane hold, if any
  *this = DemEngine(settings_, read_dem_checkpoint(file));
  meshes_ = std::move(meshes);
  outline_ = std::move(outline);
  linear_free_ = linear;
  angular_free_ = angular;
}

}  // namespace feedflow
