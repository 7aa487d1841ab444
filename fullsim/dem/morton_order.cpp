#include "fullsim/dem/morton_order.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace feedflow {
namespace {

std::uint64_t spread_bits(std::uint64_t v) {  // 21 bits -> every third bit
  v &= 0x1fffff;
  v = (v | v << 32) & 0x1f00000000ffffULL;
  v = (v | v << 16) & 0x1f0000ff0000ffULL;
  v = (v | v << 8) & 0x100f00f00f00f00fULL;
  v = (v | v << 4) & 0x10c30c30c30c30c3ULL;
  v = (v | v << 2) & 0x1249249249249249ULL;
  return v;
}

std::uint32_t cell_coordinate(double x, double lower, double cell) {
  const double c = std::floor((x - lower) / cell);
  return static_cast<std::uint32_t>(std::clamp(c, 0.0, 2097151.0));
}

}  // namespace

std::uint64_t morton_key(std::uint32_t ix, std::uint32_t iy, std::uint32_t iz) {
  return spread_bits(ix) | spread_bits(iy) << 1 | spread_bits(iz) << 2;
}

std::vector<std::size_t> morton_order(const std::vector<Vec3>& positions,
                                      const SimulationBox& box, double cell) {
  std::vector<std::uint64_t> key(positions.size());
  for (std::size_t k = 0; k < positions.size(); ++k) {
    const Vec3& x = positions[k];
    key[k] = morton_key(cell_coordinate(x.x(), box.lower.x(), cell),
                        cell_coordinate(x.y(), box.lower.y(), cell),
                        cell_coordinate(x.z(), box.lower.z(), cell));
  }
  std::vector<std::size_t> order(positions.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return key[a] < key[b]; });
  return order;
}

}  // namespace feedflow
