#include "reports/render/scene.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace feedflow::render {

void ParticleSet::check() const {
  const std::size_t n = x.size();
  if (y.size() != n || z.size() != n || radius.size() != n) {
    throw std::invalid_argument("particle set: x, y, z and radius must have the same length");
  }
  if (!value.empty() && value.size() != n) {
    throw std::invalid_argument("particle set: " + std::to_string(value.size()) + " values for " +
                                std::to_string(n) + " particles");
  }
  if (!layer.empty() && layer.size() != n) {
    throw std::invalid_argument("particle set: " + std::to_string(layer.size()) +
                                " layer ids for " + std::to_string(n) + " particles");
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!(radius[i] > 0.0) || !std::isfinite(radius[i]) || !std::isfinite(x[i]) ||
        !std::isfinite(y[i]) || !std::isfinite(z[i])) {
      throw std::invalid_argument("particle set: particle " + std::to_string(i) +
                                  " has a non-finite position or a non-positive radius");
    }
  }
}

void FieldGrid::check() const {
  if (!(cell_size > 0.0) || !std::isfinite(cell_size)) {
    throw std::invalid_argument("field grid: cell size must be positive");
  }
  if (nx <= 0 || ny <= 0) throw std::invalid_argument("field grid: nx and ny must be positive");
  const auto cells = static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny);
  if (value.size() != cells || volume_fraction.size() != cells) {
    throw std::invalid_argument("field grid: value and volume_fraction need nx * ny = " +
                                std::to_string(cells) + " entries");
  }
}

void TriangleMesh::check() const {
  if (positions.size() % 3 != 0 || indices.size() % 3 != 0) {
    throw std::invalid_argument("triangle mesh: positions and indices must come in threes");
  }
  const std::size_t vertices = positions.size() / 3;
  for (std::uint32_t k : indices) {
    if (k >= vertices) {
      throw std::invalid_argument("triangle mesh: index " + std::to_string(k) + " out of range (" +
                                  std::to_string(vertices) + " vertices)");
    }
  }
}

void Bounds3::include(Vec3 p, double pad) {
  if (empty()) {
    lo = p - Vec3{pad, pad, pad};
    hi = p + Vec3{pad, pad, pad};
    return;
  }
  lo = {std::min(lo.x, p.x - pad), std::min(lo.y, p.y - pad), std::min(lo.z, p.z - pad)};
  hi = {std::max(hi.x, p.x + pad), std::max(hi.y, p.y + pad), std::max(hi.z, p.z + pad)};
}

Bounds3 scene_bounds(const Scene& scene) {
  Bounds3 box;
  const ParticleSet& p = scene.particles;
  for (std::size_t i = 0; i < p.size(); ++i) box.include({p.x[i], p.y[i], p.z[i]}, p.radius[i]);
  if (scene.field) {
    const FieldGrid& f = *scene.field;
    box.include({f.origin_x, f.origin_y, f.plane_z});
    box.include({f.origin_x + f.nx * f.cell_size, f.origin_y + f.ny * f.cell_size, f.plane_z});
  }
  for (const WallSegment& s : scene.segments) {
    box.include(s.a);
    box.include(s.b);
  }
  for (const WallPlane& w : scene.planes) {
    box.include(w.corner);
    box.include(w.corner + w.edge_u);
    box.include(w.corner + w.edge_v);
    box.include(w.corner + w.edge_u + w.edge_v);
  }
  for (const WallCylinder& c : scene.cylinders) {
    // The bounding box of the two end discs.
    const Vec3 a = normalised(c.axis);
    const Vec3 extent{c.radius * std::sqrt(std::max(0.0, 1.0 - a.x * a.x)),
                      c.radius * std::sqrt(std::max(0.0, 1.0 - a.y * a.y)),
                      c.radius * std::sqrt(std::max(0.0, 1.0 - a.z * a.z))};
    for (const Vec3 centre : {c.base, c.base + c.length * a}) {
      box.include(centre - extent);
      box.include(centre + extent);
    }
  }
  for (const TriangleMesh& m : scene.meshes) {
    for (std::size_t k = 0; k + 2 < m.positions.size(); k += 3) {
      box.include({m.positions[k], m.positions[k + 1], m.positions[k + 2]});
    }
  }
  return box;
}

}  // namespace feedflow::render
