#pragma once
// Wall-fitted (cut) cells: how much of each cell and of each cell face lies on the material side
// of the rigid walls (models.md 2.6; the alternative to the staircase of wall_contact.hpp).
//
// A cell's open fraction is its open volume over its volume, r-weighted on the axisymmetric grid
// (int r dA over the open part); a face's aperture is its open area over its area (its open
// length, times r on the axisymmetric grid's faces of constant r, int r dr over the open part on
// those of constant z). The walls' signed distance is sampled on a lattice of s x s sub-squares
// per cell, each split into two triangles on which the distance is taken as linear: exact for a
// straight wall, a piecewise-linear wall through a kink or a corner of two walls. Faces take their
// open parts from the same lattice points, so the open region of every cell is closed by its
// faces' open parts and the wall's segments in it: a flow along a straight wall carries no net
// volume into a cut cell (plane strain; to the r-weighting's second order on the axisymmetric
// grid). Cells and faces farther than their half diagonal (half length) from every wall are
// wholly open or shut without sampling (the signed distance is 1-Lipschitz).
#include <vector>

#include "fullsim/cel/cel_fields.hpp"
#include "fullsim/cel/cel_grid.hpp"
#include "fullsim/cel/rigid_wall.hpp"

namespace feedflow::cel {

// How the grid sees an inclined wall: a staircase of solid cells (wall_contact.hpp), or cut cells
// whose open part and open faces carry the material and its transport.
enum class WallCells { staircase, cut };

struct CutCellGeometry {
  int nx = 0, ny = 0;
  std::vector<double> open;        // per cell (grid order): open volume / cell volume [-]
  std::vector<double> x_aperture;  // per face normal to x: (nx + 1) x ny, node line fastest [-]
  std::vector<double> y_aperture;  // per face normal to y: nx x (ny + 1), cell column fastest [-]

  // The face normal to `axis` on node line `along` in cell line `across` (remap_phase's order).
  double aperture(int axis, int along, int across) const {
    return axis == 0 ? x_aperture[static_cast<std::size_t>(along) +
                                  static_cast<std::size_t>(nx + 1) * across]
                     : y_aperture[static_cast<std::size_t>(across) +
                                  static_cast<std::size_t>(nx) * along];
  }
};

// Open fractions and apertures of every cell and face for the walls placed at one time
// (`subdivisions` s >= 1 sub-squares per cell edge). No walls: everything open.
CutCellGeometry cut_cell_geometry(const CelGrid& grid, const std::vector<PlacedWall>& walls,
                                  int subdivisions = 4);

// Copies the open fractions into the cells and marks the empty cells wholly inside the walls
// kSolidInsideWall (kSolidFixed cells stay). A cell holding material keeps an open fraction of at
// least its volume fraction (a wall moved into it: its material is not destroyed).
void mark_cut_cells(const CutCellGeometry& geometry, CellFields& cells);

}  // namespace feedflow::cel
