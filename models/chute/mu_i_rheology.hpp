#pragma once
// The mu(I) rheology of Jop, Forterre & Pouliquen (2006) for dense granular flow, its steady
// uniform (Bagnold) layer on an incline, and the conversions between (L, beta_P) of Pouliquen's
// law and I0 of mu(I) (reduced_models.md section 3 item 3).
#include "models/chute/pouliquen_law.hpp"

namespace feedflow {

struct MuIRheology {
  double mu_s = 0.0;      // tan theta1 [-]
  double mu_2 = 0.0;      // tan theta2 [-]
  double i0 = 0.279;      // I0 [-]
  double grain_size = 0.0;  // d [m]
  double packing = 0.6;   // solid fraction phi [-]
};

// Which velocity scale the Froude number of the flow rule uses; constants fitted with one
// differ from those of the other by sqrt(cos theta).
enum class FroudeConvention { SqrtGH, SqrtGHCosTheta };

// Throws std::invalid_argument unless 0 <= mu_s < mu_2, i0 > 0, d > 0, 0 < phi <= 1.
void check(const MuIRheology& r);

// mu(I) = mu_s + (mu_2 - mu_s)/(I0/I + 1); mu(0) = mu_s.
double friction_coefficient(const MuIRheology& r, double inertial_number);

// Inertial number of a steady uniform layer at `angle`: I0 (tan - mu_s)/(mu_2 - tan).
// Throws std::invalid_argument outside mu_s < tan(angle) < mu_2 (no steady layer).
double bagnold_inertial_number(const MuIRheology& r, double angle);

// Depth-averaged velocity of the Bagnold layer: (2/5) I sqrt(phi g cos) h^(3/2)/d [m/s];
// the surface velocity is 5/3 of it.
double bagnold_mean_velocity(const MuIRheology& r, double thickness, double angle);

// Depth-averaged inertial number of shallow-flow codes: I = (5/2) d u/(h sqrt(g h)).
double depth_averaged_inertial_number(double grain_size, double mean_velocity, double thickness);

// I0 = 5 beta d/(2 L sqrt(phi cos(match_angle))) (SqrtGH; exact at match_angle only) or
// 5 beta d/(2 L sqrt(phi)) (SqrtGHCosTheta, angle independent), and the inverses for L and beta.
double i0_from_pouliquen(double beta, double length, double grain_size, double packing,
                         double match_angle, FroudeConvention convention);
double length_from_i0(double i0, double beta, double grain_size, double packing,
                      double match_angle, FroudeConvention convention);
double beta_from_i0(double i0, double length, double grain_size, double packing,
                    double match_angle, FroudeConvention convention);

// The mu(I) rheology that matches a Pouliquen law at match_angle (mu_s = tan theta1,
// mu_2 = tan theta2, I0 from the conversion above).
MuIRheology mu_i_from_pouliquen(const PouliquenLaw& law, double grain_size, double packing,
                                double match_angle, FroudeConvention convention);

}  // namespace feedflow
