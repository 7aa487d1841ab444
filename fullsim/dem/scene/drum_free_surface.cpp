#include "fullsim/dem/scene/drum_free_surface.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

namespace feedflow {

namespace {

// The columns are one particle diameter wide from the drum's left edge; one more on each side
// takes the centres of particles pressed past the shell.
double column_width(double particle_radius) { return 2.0 * particle_radius; }
std::size_t column_count(double particle_radius, double drum_radius) {
  return static_cast<std::size_t>(std::ceil(2.0 * drum_radius / column_width(particle_radius))) + 2;
}

}  // namespace

ColumnTops column_tops(const std::vector<SurfacePoint>& particles, double particle_radius,
                       double drum_radius, std::size_t depth) {
  const double width = column_width(particle_radius);
  const std::size_t columns = column_count(particle_radius, drum_radius);
  std::vector<std::vector<double>> z(columns);
  for (const auto& p : particles) {
    const double index = std::floor((p.x + drum_radius) / width) + 1.0;
    if (index >= 0.0 && index < static_cast<double>(columns)) z[static_cast<std::size_t>(index)].push_back(p.z);
  }
  ColumnTops tops;
  tops.depth = depth;
  tops.count.resize(columns);
  tops.z.assign(columns * depth, -std::numeric_limits<double>::infinity());
  for (std::size_t c = 0; c < columns; ++c) {
    tops.count[c] = static_cast<double>(z[c].size());
    const std::size_t kept = std::min(depth, z[c].size());
    std::partial_sort(z[c].begin(), z[c].begin() + static_cast<std::ptrdiff_t>(kept), z[c].end(), std::greater<>());
    std::copy_n(z[c].begin(), kept, tops.z.begin() + static_cast<std::ptrdiff_t>(c * depth));
  }
  return tops;
}

std::vector<SurfacePoint> surface_points(const ColumnTops& tops, double particle_radius,
                                         double drum_radius, std::size_t& undetermined) {
  const double width = column_width(particle_radius);
  undetermined = 0;
  std::vector<SurfacePoint> surface;
  for (std::size_t c = 0; c < tops.count.size(); ++c) {
    if (tops.count[c] < 3.0) continue;  // a lone particle near the shell or in flight
    const double x = -drum_radius + (static_cast<double>(c) - 1.0 + 0.5) * width;
    const double* z = tops.z.data() + c * tops.depth;
    const std::size_t listed = std::min<std::size_t>(tops.depth, static_cast<std::size_t>(tops.count[c]));
    bool found = false;
    for (std::size_t k = 0; k + 1 < listed && !found; ++k)
      if (z[k] - z[k + 1] < 2.5 * particle_radius) {
        found = true;
        // A column topped by the shell (the bed against the wall above the chord's end) has
        // no free surface.
        if (std::hypot(x, z[k]) < drum_radius - 2.5 * particle_radius) surface.push_back({x, z[k]});
      }
    if (!found && listed < static_cast<std::size_t>(tops.count[c])) ++undetermined;
  }
  return surface;
}

std::vector<SurfacePoint> bed_surface_points(const std::vector<SurfacePoint>& particles,
                                             double particle_radius, double drum_radius,
                                             const std::function<void(ColumnTops&)>& merge) {
  for (std::size_t depth = 16;; depth *= 4) {
    ColumnTops tops = column_tops(particles, particle_radius, drum_radius, depth);
    if (merge) merge(tops);
    std::size_t undetermined = 0;
    auto surface = surface_points(tops, particle_radius, drum_radius, undetermined);
    if (undetermined == 0) return surface;
  }
}

}  // namespace feedflow
