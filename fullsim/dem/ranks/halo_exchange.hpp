#pragma once
// What a rank of a shared DEM run holds besides its own particles, and how it is kept up:
//  - migration (at neighbour-list rebuilds): a particle whose centre left this rank's domain
//    goes to the rank that owns it now, with its wall-contact history and the history of the
//    contacts listed under it (those with partners of larger id), so no contact forgets;
//  - ghosts: copies of the other ranks' particles within reach of this rank's domain, kept
//    behind its own particles in the store (slots owned() .. size()), rebuilt with the list;
//  - forward: the ghosts' positions and velocities from their owners, every step;
//  - reverse: the forces and torques this rank's contacts put on ghosts, added to their
//    owners' particles, every step (in rank order, so a run is deterministic for a rank count).
// A contact is computed on one rank only (the owner of its smaller id, neighbour_list.hpp).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "fullsim/dem/neighbour_list.hpp"
#include "fullsim/dem/particle_store.hpp"
#include "fullsim/dem/ranks/dem_ranks.hpp"
#include "fullsim/dem/ranks/rank_domains.hpp"

namespace feedflow {

class HaloExchange {
 public:
  // This rank's own particles: the first owned() slots of the store.
  std::size_t owned() const { return owned_; }
  // Whether the particles were shared out (the first migration done).
  bool initialised() const { return initialised_; }
  std::size_t ghosts() const { return ghosts_; }
  // The ranks ghosts come from and go to.
  const std::vector<int>& neighbour_ranks() const { return neighbours_; }

  // Keeps the own particles only (before a rebuild, a removal or a checkpoint); a store
  // without ghosts is all own.
  void drop_ghosts(ParticleStore& p);
  // After particles were added to or removed from the own ones (ghosts dropped first): every
  // slot of the store is this rank's own until the next rebuild.
  void own_all(const ParticleStore& p) {
    owned_ = p.size();
    ghosts_ = 0;
  }
  // Sends away the own particles outside this rank's domain, adds those that arrive (after the
  // own ones), and hands the contact history they bring to `list` (collective). Returns how
  // many left.
  std::size_t migrate(ParticleStore& p, NeighbourList& list, const RankDomains& domains,
                      const DemRanks& ranks);
  // Copies every own particle within `reach` of another rank's domain to that rank, and adds
  // the copies from the others as ghosts (collective).
  void build_ghosts(ParticleStore& p, const RankDomains& domains, double reach,
                    const DemRanks& ranks);
  // The ghosts' positions, velocities and angular velocities from their owners (collective).
  void forward(ParticleStore& p, const DemRanks& ranks);
  // The forces and torques on the ghosts added to their owners' particles, the ghosts' own
  // then zeroed (collective).
  void reverse(ParticleStore& p, const DemRanks& ranks);

  // Doubles sent so far by the per-step exchanges and by the rebuilds (performance block).
  double step_doubles() const { return step_doubles_; }
  double rebuild_doubles() const { return rebuild_doubles_; }

 private:
  std::size_t owned_ = 0, ghosts_ = 0;
  bool initialised_ = false;
  std::vector<int> neighbours_;
  std::vector<std::vector<std::uint32_t>> sent_;  // per neighbour: own slots copied to it
  std::vector<std::size_t> ghost_first_;          // per neighbour: its first ghost slot
  std::vector<std::size_t> ghost_count_;
  std::vector<std::vector<double>> out_, in_;  // per neighbour, reused each step
  double step_doubles_ = 0.0, rebuild_doubles_ = 0.0;
};

}  // namespace feedflow
