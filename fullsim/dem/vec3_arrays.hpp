#pragma once
// Arrays of Vec3 as flat n x 3 rows of doubles (for HDF5 datasets) and back, bit for bit.
#include <cstddef>
#include <vector>

#include "models/contact/contact_kinematics.hpp"

namespace feedflow {

inline std::vector<double> flatten(const std::vector<Vec3>& v) {
  std::vector<double> out(3 * v.size());
  for (std::size_t k = 0; k < v.size(); ++k)
    for (int a = 0; a < 3; ++a) out[3 * k + static_cast<std::size_t>(a)] = v[k][a];
  return out;
}

inline std::vector<Vec3> unflatten(const std::vector<double>& rows) {
  std::vector<Vec3> out(rows.size() / 3);
  for (std::size_t k = 0; k < out.size(); ++k)
    out[k] = Vec3(rows[3 * k], rows[3 * k + 1], rows[3 * k + 2]);
  return out;
}

}  // namespace feedflow
