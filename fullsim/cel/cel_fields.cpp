#include "fullsim/cel/cel_fields.hpp"

namespace feedflow::cel {

void CellFields::resize(std::size_t cells) {
  volume_fraction.assign(cells, 0.0);
  mass.assign(cells, 0.0);
  stress.assign(cells, Eigen::Matrix3d::Zero());
  void_ratio.assign(cells, 0.0);
  solid.assign(cells, 0);
  wave_speed.assign(cells, 0.0);
  volume_rate.assign(cells, 0.0);
  corner_force.assign(cells * kNodesPerCell, NodeVector::Zero());
}

void NodeFields::resize(std::size_t nodes) {
  velocity.assign(nodes, NodeVector::Zero());
  mass.assign(nodes, 0.0);
  force.assign(nodes, NodeVector::Zero());
  constraint.assign(nodes, 0);
}

}  // namespace feedflow::cel
