#pragma once
// Linked cells plus a half Verlet list with a skin. Each pair is listed once, under the
// particle with the smaller id (so a pair keeps its orientation, and the sign of its
// tangential and rolling history, across re-sorting). The list is compressed by rows: the
// neighbours of slot i are partner[first[i] .. first[i+1]). Each entry carries its contact
// history (history_size() doubles) right beside it; a rebuild matches the new pairs to the old
// ones by particle ids and carries their history over. No map is consulted in the pair loop.
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "fullsim/dem/particle_store.hpp"
#include "fullsim/dem/simulation_box.hpp"

namespace feedflow {

class NeighbourList {
 public:
  NeighbourList() = default;
  NeighbourList(double skin, std::size_t history_size)
      : skin_(skin), history_size_(history_size) {}

  // Rebuilds from the current positions (wrapped into the box along periodic axes first) and
  // carries the history of surviving pairs over. Remembers the positions for needs_rebuild().
  // On a rank that holds ghost copies behind its `owned` particles, a pair is listed only
  // when the particle with the smaller id is its own (the ghost's rank lists the others); the
  // rows of the ghosts stay empty.
  void rebuild(ParticleStore& particles, const SimulationBox& box,
               std::size_t owned = static_cast<std::size_t>(-1));
  // The history of a contact brought by a particle from another rank, carried over by the
  // next rebuild as if it had been listed here.
  void import_history(std::uint64_t key, const double* h);
  // True when a particle moved more than skin/2 since the last rebuild (or the particle count
  // changed).
  bool needs_rebuild(const ParticleStore& particles) const;
  // The largest displacement since the last rebuild [m].
  double max_displacement(const ParticleStore& particles) const;
  // The positions at the last rebuild (slot order of that rebuild).
  const std::vector<Vec3>& reference_positions() const { return reference_; }

  double skin() const { return skin_; }
  double cell_size() const { return cell_size_; }
  std::size_t history_size() const { return history_size_; }
  std::size_t pair_count() const { return partner.size(); }
  std::size_t rebuild_count() const { return rebuilds_; }
  // Contacts carried over by the last rebuild (history found and moved to the new entry).
  std::size_t carried_over() const { return carried_; }

  std::vector<std::uint32_t> first;    // size n + 1
  std::vector<std::uint32_t> partner;  // slot j of each entry
  std::vector<double> history;         // history_size() doubles per entry

  // The id pair (id_i << 32 | id_j) of each entry.
  const std::vector<std::uint64_t>& entry_keys() const { return entry_key_; }

  // A list as saved in a checkpoint (entries, their id pairs and history, the positions at the
  // last rebuild, the counters), taken as is.
  static NeighbourList restored(double skin, std::size_t history_size, double cell_size,
                                std::size_t rebuilds, std::size_t carried,
                                std::vector<std::uint32_t> first, std::vector<std::uint32_t> partner,
                                std::vector<double> history, std::vector<std::uint64_t> keys,
                                std::vector<Vec3> reference) {
    NeighbourList l(skin, history_size);
    l.cell_size_ = cell_size;
    l.rebuilds_ = rebuilds;
    l.carried_ = carried;
    l.first = std::move(first);
    l.partner = std::move(partner);
    l.history = std::move(history);
    l.entry_key_ = std::move(keys);
    l.reference_ = std::move(reference);
    return l;
  }

  // The history of the pair of ids (a, b), or nullptr when not listed (tests, diagnostics).
  const double* find_history(std::uint32_t id_a, std::uint32_t id_b) const;

 private:
  double skin_ = 0.0;
  std::size_t history_size_ = 0;
  double cell_size_ = 0.0;
  std::size_t rebuilds_ = 0;
  std::size_t carried_ = 0;
  std::vector<Vec3> reference_;            // positions at the last rebuild
  std::vector<std::uint64_t> entry_key_;   // (id_i << 32 | id_j) of each entry
};

}  // namespace feedflow
