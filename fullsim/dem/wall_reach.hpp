#pragma once
// Which walls each particle can touch before the next neighbour-list rebuild. Between two
// rebuilds no particle moves more than half the skin from where it stood at the last one, so a
// still wall farther than its radius plus the skin from a particle now cannot touch it until
// the next rebuild; the wall loop then skips that wall for that particle (no distance test, no
// mesh-grid query: in a hopper most grains are far from every wall). A wall that moves, or a
// particle whose walls do not fit in the mask, is always tested. Skipping changes no result:
// a skipped wall had no contact, and a contact that ended cleared its history on the step it
// ended, while the wall was still in reach.
#include <cstdint>
#include <vector>

#include "fullsim/dem/mesh_wall.hpp"
#include "fullsim/dem/particle_store.hpp"
#include "fullsim/dem/wall.hpp"

namespace feedflow {

class WallReach {
 public:
  // Bit k: analytic wall k; bit walls.size() + m: mesh m. 64 walls and meshes at most are
  // sorted out; more leave every wall in reach of every particle.
  static constexpr std::size_t kMaxSorted = 64;

  // Takes the walls within radius + `margin` of each particle (margin: the neighbour skin).
  void update(const ParticleStore& particles, const std::vector<Wall>& walls,
              const std::vector<MeshWall>& meshes, double margin);
  // The mask of particle slot i (valid until the particles are added, removed or reordered).
  std::uint64_t mask(std::size_t i) const { return mask_[i]; }
  const std::uint64_t* data() const { return mask_.data(); }
  std::size_t size() const { return mask_.size(); }
  // Particle-wall pairs in reach at the last update, over particles x walls (a share in 0..1).
  double share_in_reach() const { return share_; }

 private:
  std::vector<std::uint64_t> mask_;
  double share_ = 1.0;
};

}  // namespace feedflow
