#pragma once
// The remap phase (models.md 2.4): after the Lagrangian phase the cell contents (material volume
// vf V^L, mass, stress x material volume, void ratio x mass, cell momentum) are transported back
// to the fixed grid by face fluxes, split into an x and a y sweep whose order alternates every
// step. A face's transport volume dV is dt h times the mean normal velocity of its two nodes;
// the donor (upwind) cell gives a material volume dVm (RemapOptions::material_flux: donor cell
// vf_D dV, a van Leer limited MUSCL face value of vf, or the PLIC cut of plic_interface; a
// fragment with no material around it moves as donor cell), and
// with it mass rho_f dVm, stress T_f dVm and void mass e_f rho_f dVm, where the face states are
// the donor's (first order) or van Leer limited MUSCL face values (limited_slope.hpp; slopes
// only between cells that both hold material, first order next to void, walls and box faces).
// Every flux leaves one cell and enters its neighbour,
// so mass, material volume and cell momentum are conserved to round-off; the faces of solid
// cells carry no flux, nor do the box faces except outflow faces: there the boundary cell is the
// donor of an outward flux (the mass and momentum leave the grid and are reported), an inward
// flux brings void only.
//
// Momentum: half-index shift (Benson 1992). Nodes are the cells of the dual grid; the mass flux
// through a dual face (at a cell centre) is half the sum of that cell's two primal face fluxes,
// shared by the two dual lines the cell touches, so the advected nodal mass equals the mass lumped
// from the remapped cells. Nodal momentum moves with these fluxes at the donor node's velocity
// (donor cell): conservative, and the new velocity is a convex combination of old ones (no
// overshoot at nodes that lose most of their mass); or, with `second_order_momentum`, at the
// donor's van Leer limited MUSCL face velocity along the node line (still conservative; the
// face value lies between the donor's and its downwind neighbour's).
//
// Grain-consistent volume (`set_grain_density`, used by CelSolver): a granular skeleton's volume
// is fixed by its mass and void ratio, V_m = M (1 + e) / rho_g with the grain density rho_g =
// rho (1 + e) of the material. With it the material volume at the start of the remap is M (1 + e)
// / rho_g (not vf V^L), a face carries the mass rho_g dVm / (1 + e_f), and after each sweep the
// material volume is taken again from the cell's mass and void mass. So the density of every cell
// stays rho_g / (1 + e): a cell can neither keep the mass of a denser state than its void ratio
// allows nor thin out to a foam. A cell whose material no longer fits (V_m > V) keeps vf = 1 and
// its void ratio is lowered until it fits (`RemapReport::compacted_cells`), but not below the
// densest state the law allows at its pressure, e_d0 exp(-(-tr T / h_s)^n) (`DensestState`):
// a cell that would need more keeps that void ratio with vf = 1 and a density above rho_g /
// (1 + e) (`RemapReport::overpacked_cells`). Cells at a wall's staircase (touching a solid cell
// across a face or a corner) are not compacted: their nodes carry the material along the wall,
// across the step's shut faces and into the cut cells' parts inside the wall, but the shut faces
// carry no flux and a cut cell counts its whole volume, so such cells fill up with material that
// is on its way past the step, not denser. They keep their void ratio with vf = 1 and a material
// volume above the cell's, which their next fluxes export (a donor gives vf dV with vf > 1)
// (`RemapReport::wall_overfilled_cells`). Compacting them instead turned a cone's staircase,
// where the hoop rate adds to the inflow, into a dense stagnant wall band
// (funnel flow at 10-25 deg). Without a grain density the material volume is vf V^L and an
// overfilled cell keeps its mass with a higher density.
#include <cstdint>
#include <vector>

#include "fullsim/cel/box_walls.hpp"
#include "fullsim/cel/cel_fields.hpp"
#include "fullsim/cel/cut_cells.hpp"

namespace feedflow::cel {

// How the cell state and the material volume are advected. Defaults: first order everywhere
// (the measured choice, see fullsim/README.md cel/).
enum class MaterialFlux { donor_cell, limited, plic };
struct RemapOptions {
  // Second-order (van Leer MUSCL) face values per cell quantity; all false: donor cell.
  bool second_order_stress = false;
  bool second_order_void_ratio = false;
  bool second_order_density = false;
  // Nodal momentum at van Leer MUSCL face velocities of the dual grid (between nodes that both
  // carry mass; donor node velocity next to void and at the box faces).
  bool second_order_momentum = false;
  MaterialFlux material_flux = MaterialFlux::donor_cell;
  // A neighbour takes part in a slope only above this volume fraction.
  double slope_volume_fraction = 1e-3;
};
// Second order for the whole cell state (stress, void ratio, density); the nodal momentum
// stays donor cell (second_order_momentum is its own switch).
RemapOptions second_order_state(RemapOptions o = {});

struct RemapReport {
  double max_outflow_fraction = 0.0;  // largest share of a donor's volume given in one sweep
  double removed_mass = 0.0;          // in cells that fell below the volume-fraction cut [kg/m]
  NodeVector lost_momentum = NodeVector::Zero();  // on nodes that became void [kg m/s /m]
  double outflow_mass = 0.0;                          // through outflow faces [kg/m]
  NodeVector outflow_momentum = NodeVector::Zero();   // nodal, through outflow faces [kg m/s /m]
  double largest_volume_fraction = 0.0;   // of the remapped cells before clipping to 1 [-]
  double smallest_volume_fraction = 0.0;  // of the remapped cells, before the cut [-]
  int compacted_cells = 0;   // grain-consistent: overfilled cells whose void ratio was lowered
  int overpacked_cells = 0;  // of those, cells at the densest state with rho > rho_g / (1 + e)
  int wall_overfilled_cells = 0;  // at a staircase step: overfilled, void ratio kept
};

// The densest void ratio of the law at a stress: e_d0 exp(-(-tr T / h_s)^n) (Bauer).
struct DensestState {
  double e_d0 = 0.0, h_s = 1.0, n = 1.0;
  double void_ratio(const Eigen::Matrix3d& stress) const;
};

class RemapPhase {
 public:
  // Cells whose volume fraction falls below `volume_fraction_cut` are emptied (mass booked).
  explicit RemapPhase(const RemapOptions& options = {}, double volume_fraction_cut = 1e-12)
      : options_(options), cut_(volume_fraction_cut) {}
  const RemapOptions& options() const { return options_; }
  // rho_g = rho (1 + e) [kg/m^3]; 0 (the default) leaves the material volume vf V^L.
  void set_grain_density(double rho_g, const DensestState& densest = {}) {
    grain_density_ = rho_g;
    densest_ = densest;
  }
  double grain_density() const { return grain_density_; }
  // Cut cells (cut_cells.hpp): a face carries flux through its aperture, a cell holds material in
  // its open part. nullptr (the default): the staircase, where solid cells' faces are shut.
  void set_cut_cells(const CutCellGeometry* geometry) { cut_cells_ = geometry; }

  // `x_first` chooses the sweep order. Node masses are re-lumped; velocities get the
  // constraints applied.
  RemapReport remap(const CelGrid& grid, const BoxWalls& walls, double dt, bool x_first,
                    double void_node_mass, CellFields& cells, NodeFields& nodes);

 private:
  struct Contents {
    std::vector<double> volume, material_volume, mass, void_mass;
    std::vector<Eigen::Matrix3d> stress_volume;
    void resize(std::size_t n);
  };
  struct SweepResult {
    double worst_share = 0.0, outflow_mass = 0.0;
  };
  SweepResult sweep(const CelGrid& grid, double dt, int axis, const CellFields& cells,
                    const NodeFields& nodes);
  // Transport volume through the face normal to `axis` on node line `along` in cell line `across`,
  // positive towards the higher cell [m^3/m or m^3/rad].
  double transport_volume(const CelGrid& grid, const NodeFields& nodes, int axis, int along,
                          int across, double dt, const CellFields& cells) const;
  void refresh_cell_state(const CelGrid& grid, const CellFields& cells);
  // Material volume given by `donor` through a face of transport volume |dv| on its `toward`
  // side (+1 high, -1 low) along `axis`.
  double material_flux(const CelGrid& grid, const CellFields& cells, int axis,
                       std::size_t donor, double dv, double toward) const;
  NodeVector sweep_momentum(const CelGrid& grid, int axis);  // returns the outflow

  // Material volume of cell c from its current contents (grain-consistent mode).
  double grain_volume(std::size_t c) const {
    return (now_.mass[c] + now_.void_mass[c]) / grain_density_;
  }

  RemapOptions options_;
  double cut_;
  double grain_density_ = 0.0;
  DensestState densest_{};
  const CutCellGeometry* cut_cells_ = nullptr;
  bool outflow_lo_[kDimension] = {false, false};  // left, bottom
  bool outflow_hi_[kDimension] = {false, false};  // right, top
  Contents now_, delta_;
  // Per cell at the start of a sweep: volume fraction, density, void ratio, stress, and whether
  // the cell may enter a slope (material above the slope threshold, not solid).
  std::vector<double> vf_, rho_, e_;
  std::vector<Eigen::Matrix3d> stress_;
  std::vector<std::uint8_t> slope_cell_;
  std::vector<double> cut_off_;         // mass removed per cell by the cut, this remap [kg/m]
  std::vector<double> face_mass_flux_;  // of the last sweep, per line (n_along + 1 faces) [kg/m]
  std::vector<double> node_mass_, node_mass_delta_;
  std::vector<NodeVector> node_momentum_, node_momentum_delta_;
};

}  // namespace feedflow::cel
