#include "fullsim/dem/neighbour_list.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

namespace feedflow {
namespace {

std::uint64_t pair_key(std::uint32_t a, std::uint32_t b) {
  return static_cast<std::uint64_t>(a) << 32 | b;
}

// The cell grid over the box: cells at least `cutoff` wide.
struct CellGrid {
  std::array<int, 3> count{1, 1, 1};
  Vec3 lower = Vec3::Zero();
  Vec3 size = Vec3::Ones();

  CellGrid(const SimulationBox& box, double cutoff) {
    lower = box.lower;
    const Vec3 length = box.length();
    for (int a = 0; a < 3; ++a) {
      count[a] = std::max(1, static_cast<int>(std::floor(length[a] / cutoff)));
      count[a] = std::min(count[a], 1 << 10);
      size[a] = length[a] / count[a];
    }
  }
  int coordinate(double x, int a) const {
    return std::clamp(static_cast<int>(std::floor((x - lower[a]) / size[a])), 0, count[a] - 1);
  }
  std::size_t cells() const {
    return static_cast<std::size_t>(count[0]) * static_cast<std::size_t>(count[1]) *
           static_cast<std::size_t>(count[2]);
  }
  std::size_t index(int ix, int iy, int iz) const {
    return (static_cast<std::size_t>(iz) * static_cast<std::size_t>(count[1]) +
            static_cast<std::size_t>(iy)) * static_cast<std::size_t>(count[0]) +
           static_cast<std::size_t>(ix);
  }
};

}  // namespace

void NeighbourList::import_history(std::uint64_t key, const double* h) {
  entry_key_.push_back(key);
  history.insert(history.end(), h, h + history_size_);
}

void NeighbourList::rebuild(ParticleStore& particles, const SimulationBox& box, std::size_t owned) {
  const std::size_t n = particles.size();
  const std::size_t rows = std::min(owned, n);
  if (box.any_periodic())
    for (auto& x : particles.position) x = box.wrap(x);

  // Old contacts with history, sorted by their id pair, for the carry-over.
  std::vector<std::uint32_t> old_order;
  if (history_size_ > 0) {
    for (std::size_t e = 0; e < entry_key_.size(); ++e) {
      const double* h = history.data() + e * history_size_;
      if (std::any_of(h, h + history_size_, [](double v) { return v != 0.0; }))
        old_order.push_back(static_cast<std::uint32_t>(e));
    }
    std::sort(old_order.begin(), old_order.end(),
              [&](std::uint32_t a, std::uint32_t b) { return entry_key_[a] < entry_key_[b]; });
  }

  const double cutoff = 2.0 * particles.max_radius() + skin_;
  const CellGrid grid(box, cutoff);
  cell_size_ = std::min({grid.size.x(), grid.size.y(), grid.size.z()});
  // Linked cells: head of each cell, next particle in the same cell.
  std::vector<std::int32_t> head(grid.cells(), -1);
  std::vector<std::int32_t> next(n, -1);
  std::vector<std::array<int, 3>> cell_of(n);
  for (std::size_t k = n; k-- > 0;) {
    const Vec3& x = particles.position[k];
    cell_of[k] = {grid.coordinate(x.x(), 0), grid.coordinate(x.y(), 1), grid.coordinate(x.z(), 2)};
    const std::size_t c = grid.index(cell_of[k][0], cell_of[k][1], cell_of[k][2]);
    next[k] = head[c];
    head[c] = static_cast<std::int32_t>(k);
  }

  std::vector<std::uint32_t> new_partner;
  std::vector<std::uint64_t> new_key;
  new_partner.reserve(n * 8);
  new_key.reserve(n * 8);
  first.assign(n + 1, 0);
  std::vector<std::size_t> stencil;
  for (std::size_t i = 0; i < rows; ++i) {
    first[i] = static_cast<std::uint32_t>(new_partner.size());
    const Vec3& xi = particles.position[i];
    const std::uint32_t idi = particles.id[i];
    // The distinct neighbouring cells (a periodic axis with fewer than 3 cells repeats them).
    stencil.clear();
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          std::array<int, 3> c{cell_of[i][0] + dx, cell_of[i][1] + dy, cell_of[i][2] + dz};
          bool inside = true;
          for (int a = 0; a < 3; ++a) {
            if (c[a] >= 0 && c[a] < grid.count[a]) continue;
            if (box.periodic[a]) c[a] = (c[a] + grid.count[a]) % grid.count[a];
            else inside = false;
          }
          if (inside) stencil.push_back(grid.index(c[0], c[1], c[2]));
        }
    std::sort(stencil.begin(), stencil.end());
    stencil.erase(std::unique(stencil.begin(), stencil.end()), stencil.end());
    for (std::size_t c : stencil)
      for (std::int32_t j = head[c]; j >= 0; j = next[static_cast<std::size_t>(j)]) {
        const auto sj = static_cast<std::size_t>(j);
        if (particles.id[sj] <= idi) continue;
        const Vec3 d = box.minimum_image(xi - particles.position[sj]);
        const double reach = particles.radius[i] + particles.radius[sj] + skin_;
        if (d.squaredNorm() < reach * reach) {
          new_partner.push_back(static_cast<std::uint32_t>(j));
          new_key.push_back(pair_key(idi, particles.id[sj]));
        }
      }
  }
  for (std::size_t i = rows; i <= n; ++i) first[i] = static_cast<std::uint32_t>(new_partner.size());

  std::vector<double> new_history(new_partner.size() * history_size_, 0.0);
  carried_ = 0;
  if (!old_order.empty()) {
    for (std::size_t e = 0; e < new_key.size(); ++e) {
      auto it = std::lower_bound(old_order.begin(), old_order.end(), new_key[e],
                                 [&](std::uint32_t a, std::uint64_t k) { return entry_key_[a] < k; });
      if (it == old_order.end() || entry_key_[*it] != new_key[e]) continue;
      std::copy_n(history.begin() + static_cast<std::ptrdiff_t>(*it * history_size_), history_size_,
                  new_history.begin() + static_cast<std::ptrdiff_t>(e * history_size_));
      ++carried_;
    }
  }
  partner.swap(new_partner);
  entry_key_.swap(new_key);
  history.swap(new_history);
  reference_ = particles.position;
  ++rebuilds_;
}

double NeighbourList::max_displacement(const ParticleStore& particles) const {
  double d2 = 0.0;
  for (std::size_t k = 0; k < particles.size(); ++k)
    d2 = std::max(d2, (particles.position[k] - reference_[k]).squaredNorm());
  return std::sqrt(d2);
}

bool NeighbourList::needs_rebuild(const ParticleStore& particles) const {
  if (reference_.size() != particles.size()) return true;
  const double limit2 = 0.25 * skin_ * skin_;
  for (std::size_t k = 0; k < particles.size(); ++k)
    if ((particles.position[k] - reference_[k]).squaredNorm() > limit2) return true;
  return false;
}

const double* NeighbourList::find_history(std::uint32_t id_a, std::uint32_t id_b) const {
  const std::uint64_t key = pair_key(std::min(id_a, id_b), std::max(id_a, id_b));
  for (std::size_t e = 0; e < entry_key_.size(); ++e)
    if (entry_key_[e] == key) return history.data() + e * history_size_;
  return nullptr;
}

}  // namespace feedflow
