#include "fullsim/dem/triangle_mesh.hpp"

namespace feedflow {

std::uint32_t TriangleMesh::weld(const Vec3& x) {
  const auto key = std::make_tuple(x.x() + 0.0, x.y() + 0.0, x.z() + 0.0);  // -0 welds to +0
  const auto [it, added] = welded_.emplace(key, static_cast<std::uint32_t>(vertices.size()));
  if (added) vertices.push_back(Vec3(std::get<0>(key), std::get<1>(key), std::get<2>(key)));
  return it->second;
}

void TriangleMesh::add_triangle(const Vec3& a, const Vec3& b, const Vec3& c,
                                std::size_t position) {
  const double longest2 =
      std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
  // Collinear within round-off: twice the area below 1e-12 of the longest edge squared.
  if (!((b - a).cross(c - a).norm() > 1e-12 * longest2)) {
    degenerate.push_back(position);
    return;
  }
  const std::uint32_t i = weld(a), j = weld(b), k = weld(c);
  if (i == j || j == k || k == i) {
    degenerate.push_back(position);
    return;
  }
  triangles.push_back({i, j, k});
}

}  // namespace feedflow
