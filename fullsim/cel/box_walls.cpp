#include "fullsim/cel/box_walls.hpp"

#include "fullsim/cel/quad_cell.hpp"

namespace feedflow::cel {
namespace {

std::uint8_t face_bits(WallCondition w, NodeConstraint normal) {
  switch (w) {
    case WallCondition::open:
    case WallCondition::outflow: return 0;
    case WallCondition::free_slip: return static_cast<std::uint8_t>(normal);
    case WallCondition::no_slip: return static_cast<std::uint8_t>(NodeConstraint::fixed);
  }
  return 0;
}

}  // namespace

void assign_node_constraints(const CelGrid& grid, const BoxWalls& walls,
                             const CellFields& cells, NodeFields& nodes) {
  for (std::size_t a = 0; a < grid.node_count(); ++a) {
    const int i = grid.node_i(a), j = grid.node_j(a);
    std::uint8_t bits = 0;
    if (i == 0) bits |= face_bits(walls.left, NodeConstraint::fixed_x);
    if (i == grid.nx) bits |= face_bits(walls.right, NodeConstraint::fixed_x);
    if (j == 0) bits |= face_bits(walls.bottom, NodeConstraint::fixed_y);
    if (j == grid.ny) bits |= face_bits(walls.top, NodeConstraint::fixed_y);
    nodes.constraint[a] = bits;
  }
  for (std::size_t c = 0; c < grid.cell_count(); ++c) {
    if (cells.solid[c] != kSolidFixed) continue;  // wall cells are left to the contact
    for (std::size_t a : grid.cell_nodes(c))
      nodes.constraint[a] = static_cast<std::uint8_t>(NodeConstraint::fixed);
  }
}

void apply_node_constraints(NodeFields& nodes) {
  const auto fx = static_cast<std::uint8_t>(NodeConstraint::fixed_x);
  const auto fy = static_cast<std::uint8_t>(NodeConstraint::fixed_y);
  for (std::size_t a = 0; a < nodes.velocity.size(); ++a) {
    const std::uint8_t bits = nodes.constraint[a];
    if (bits & fx) nodes.velocity[a].x() = 0.0;
    if (bits & fy) nodes.velocity[a].y() = 0.0;
  }
}

}  // namespace feedflow::cel
