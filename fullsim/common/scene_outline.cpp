#include "fullsim/common/scene_outline.hpp"

#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

#include "fullsim/common/hdf5_file.hpp"

namespace feedflow {

SceneOutline circle_outline(const Eigen::Vector3d& centre, const Eigen::Vector3d& axis,
                            double radius, int segments) {
  const Eigen::Vector3d n = axis.normalized(), u = n.unitOrthogonal(), v = n.cross(u);
  auto at = [&](int k) {
    const double phi = 2.0 * std::numbers::pi * k / segments;
    return Eigen::Vector3d(centre + radius * (std::cos(phi) * u + std::sin(phi) * v));
  };
  SceneOutline out;
  for (int k = 0; k < segments; ++k) out.push_back({at(k), at(k + 1)});
  return out;
}

void write_outline(Hdf5File& file, const std::string& path, const SceneOutline& outline) {
  if (outline.empty()) return;
  std::vector<double> points;
  for (const auto& s : outline)
    points.insert(points.end(), {s.a.x(), s.a.y(), s.a.z(), s.b.x(), s.b.y(), s.b.z()});
  file.write(path, points, {outline.size(), 6}, "m");
}

SceneOutline read_outline(const Hdf5File& file, const std::string& path) {
  if (!file.exists(path)) return {};
  const auto dims = file.dims(path);
  if (dims.size() != 2 || dims[1] != 6) return {};
  const auto points = file.read<double>(path);
  SceneOutline out(dims[0]);
  for (std::size_t k = 0; k < out.size(); ++k) {
    const double* p = &points[6 * k];
    out[k] = {{p[0], p[1], p[2]}, {p[3], p[4], p[5]}};
  }
  return out;
}

}  // namespace feedflow
