#include "fullsim/dem/bed_view.hpp"

#include "fullsim/dem/ranks/gathered_particles.hpp"

namespace feedflow {

double BedView::total_mass() const { return ranks_.sum(store_.total_mass(own_)); }

double BedView::kinetic_energy() const { return ranks_.sum(store_.kinetic_energy(own_)); }

ParticleStore BedView::gathered(const std::function<bool(std::size_t)>& inside) const {
  return all_gather_particles(store_, own_, ranks_, inside);
}

}  // namespace feedflow
