#pragma once
// What a scene measures of the bed: this rank's own particles and the reductions that turn a
// measurement of each rank's share into one of every rank's particles (sums, maxima, the
// highest values per bin, the particles of a region). A scene loops over its own particles and
// reduces; it never holds the whole bed. Alone, the own particles are all of them and every
// reduction is the value itself. On a run shared among ranks every reduction is collective:
// every rank calls the same ones in the same order, and gets the same answer.
#include <cstddef>
#include <functional>
#include <vector>

#include "fullsim/dem/particle_store.hpp"
#include "fullsim/dem/ranks/dem_ranks.hpp"

namespace feedflow {

class BedView {
 public:
  // `own`: the first slots of `store` this rank owns (ghost copies behind them are left out).
  BedView(const ParticleStore& store, std::size_t own, DemRanks ranks)
      : store_(store), own_(own), ranks_(ranks) {}

  // This rank's particles: slots [0, own()) of store().
  const ParticleStore& store() const { return store_; }
  std::size_t own() const { return own_; }

  // Of every rank's particles.
  double count() const { return ranks_.sum(static_cast<double>(own_)); }
  double total_mass() const;
  double kinetic_energy() const;

  double sum(double value) const { return ranks_.sum(value); }
  void sum(std::vector<double>& values) const { ranks_.sum(values); }
  double max(double value) const { return ranks_.max(value); }
  void max(std::vector<double>& values) const { ranks_.max(values); }
  // Per bin, the k largest values of every rank's (DemRanks::highest): `tops` holds each bin's
  // k values of this rank in descending order, padded with -infinity.
  void highest(std::vector<double>& tops, std::size_t k) const { ranks_.highest(tops, k); }

  // Every rank's particles whose slot `inside` accepts, in one store (collective; alone, a copy
  // of the accepted ones), for a test that needs the particles themselves, e.g. near a point.
  ParticleStore gathered(const std::function<bool(std::size_t)>& inside) const;

 private:
  const ParticleStore& store_;
  std::size_t own_;
  DemRanks ranks_;
};

}  // namespace feedflow
