#include "fullsim/cel/cel_fields.hpp"

#include <algorithm>

namespace feedflow::cel {

void CellFields::resize(std::size_t cells) {
  volume_fraction.assign(cells, 0.0);
  mass.assign(cells, 0.0);
  stress.assign(cells, Eigen::Matrix3d::Zero());
  void_ratio.assign(cells, 0.0);
  solid.assign(cells, 0);
  open_fraction.assign(cells, 1.0);
  wave_speed.assign(cells, 0.0);
  volume_rate.assign(cells, 0.0);
  corner_force.assign(cells * kNodesPerCell, NodeVector::Zero());
}

bool at_staircase(const CelGrid& g, const CellFields& cells, std::size_t c) {
  if (cells.open_fraction[c] < 1.0) return true;
  const int i = g.cell_i(c), j = g.cell_j(c);
  for (int jj = std::max(j - 1, 0); jj <= std::min(j + 1, g.ny - 1); ++jj)
    for (int ii = std::max(i - 1, 0); ii <= std::min(i + 1, g.nx - 1); ++ii)
      if (cells.solid[g.cell(ii, jj)]) return true;
  return false;
}

void NodeFields::resize(std::size_t nodes) {
  velocity.assign(nodes, NodeVector::Zero());
  mass.assign(nodes, 0.0);
  force.assign(nodes, NodeVector::Zero());
  constraint.assign(nodes, 0);
}

}  // namespace feedflow::cel
