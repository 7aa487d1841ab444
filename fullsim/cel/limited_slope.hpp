#pragma once
// Limited slopes and face values of the second-order (MUSCL) remap, models.md 2.4 item 3
// (van Leer 1977): a cell's content is linear across the cell with a slope limited by the van
// Leer harmonic mean of the two one-sided differences (zero at an extremum), and a flux of
// Courant number C carries the mean of that line over the slab it takes next to the face,
// psi_f = psi_D + (1/2) (1 - C) Delta_D toward the face. The face value lies between the donor's
// value and its downwind neighbour's, so the sweep adds no new extremum (1D, C <= 1).
namespace feedflow::cel {

// van Leer's limited difference per cell of two one-sided differences (left: psi_D - psi_{D-1},
// right: psi_{D+1} - psi_D); 0 when they differ in sign or one is zero.
inline double van_leer_difference(double left, double right) {
  const double p = left * right;
  return p > 0.0 ? 2.0 * p / (left + right) : 0.0;
}

// The mean over the outgoing slab of the donor's line: `toward` is +1 when the face is on the
// donor's high side, -1 on its low side; `courant` = |dV| / V_D.
inline double muscl_face_value(double donor, double limited_difference, double courant,
                               double toward) {
  return donor + 0.5 * (1.0 - courant) * toward * limited_difference;
}

}  // namespace feedflow::cel
