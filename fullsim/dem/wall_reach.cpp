#include "fullsim/dem/wall_reach.hpp"

#include <array>
#include <bit>

namespace feedflow {

void WallReach::update(const ParticleStore& particles, const std::vector<Wall>& walls,
                       const std::vector<MeshWall>& meshes, double margin) {
  const std::size_t n = particles.size();
  const std::size_t nw = walls.size(), nm = meshes.size();
  mask_.assign(n, ~std::uint64_t{0});
  share_ = 1.0;
  if (nw + nm == 0 || nw + nm > kMaxSorted) return;
  std::uint64_t always = 0;  // walls that move are tested every step
  for (std::size_t k = 0; k < nw; ++k)
    if (walls[k].moves()) always |= std::uint64_t{1} << k;
  for (std::size_t m = 0; m < nm; ++m)
    if (meshes[m].moves()) always |= std::uint64_t{1} << (nw + m);
  std::size_t in_reach = 0;
#pragma omp parallel for schedule(static) reduction(+ : in_reach) if (n >= 4096)
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& x = particles.position[i];
    const double reach = particles.radius[i] + margin;
    std::uint64_t bits = always;
    for (std::size_t k = 0; k < nw; ++k)
      if (walls[k].touch(x).gap < reach) bits |= std::uint64_t{1} << k;
    std::array<MeshTouch, MeshWall::kMaxContacts> touch;
    for (std::size_t m = 0; m < nm; ++m)
      if (meshes[m].touches(x, reach, touch) > 0) bits |= std::uint64_t{1} << (nw + m);
    mask_[i] = bits;
    in_reach += static_cast<std::size_t>(std::popcount(bits));
  }
  if (n > 0) share_ = static_cast<double>(in_reach) / static_cast<double>(n * (nw + nm));
}

}  // namespace feedflow
