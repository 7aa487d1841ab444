#pragma once
// PLIC interface reconstruction in a mixed cell (Youngs 1982; models.md 2.4 item 2c): the
// material/void boundary in the cell is a straight line whose normal is minus the volume-fraction
// gradient (Youngs' 3x3 stencil) and whose offset cuts the cell to its volume fraction; a face
// flux of the remap then takes the material inside the slab of the flux's width next to the face
// instead of vf_D times the slab. Two-dimensional: the cell is a rectangle [0, a] x [0, b] in
// sweep coordinates (along, across); the material lies on n . x <= alpha.
#include <array>

#include "fullsim/cel/cel_grid.hpp"

namespace feedflow::cel {

// Unit normal from the material into the void from a 3x3 block of volume fractions around the
// cell, f[(di + 1) + 3 (dj + 1)] for the neighbour (i + di, j + dj); zero if the block is uniform.
NodeVector youngs_normal(const std::array<double, 9>& f);

struct CutRectangle {
  double a = 0.0, b = 0.0;             // extent along x and y
  NodeVector n = NodeVector::Zero();   // unit normal into the void
  double alpha = 0.0;                  // the line n . x = alpha, material below
};

// The line with normal n that leaves `fraction` (0..1) of the rectangle [0, a] x [0, b] on its
// material side (to 1e-14 of the area; Illinois regula falsi on the offset, the cut area being
// monotone in it).
CutRectangle cut_rectangle(double a, double b, const NodeVector& n, double fraction);

// Material area of the cut rectangle inside the slab x0 <= x <= x1 (0 <= x0 <= x1 <= a).
double material_area(const CutRectangle& cut, double x0, double x1);

}  // namespace feedflow::cel
