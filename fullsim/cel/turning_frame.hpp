#pragma once
// A frame of reference turning with a drum (models.md 2.6; the moving-reference-frame method of
// rotating machinery): from `start` on the solver works in the frame that turns at
// `angular_velocity` (counter-clockwise positive) about `centre`, so the shell is at rest on
// the grid and only material that moves relative to it is advected. In that frame gravity turns
// the other way, g' = R(-theta) g with theta = omega (t - start), and every node carries the
// centrifugal and Coriolis forces m (omega^2 (x - c) - 2 omega x v). Velocities in the frame are
// relative to the shell; `to_lab` turns a frame direction back into the laboratory.
#include <Eigen/Core>
#include <limits>

#include "fullsim/cel/cel_fields.hpp"

namespace feedflow::cel {

struct TurningFrame {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();  // [m]
  double angular_velocity = 0.0;                     // [rad/s]; 0: the laboratory frame
  double start = std::numeric_limits<double>::infinity();  // [s]

  bool turning(double t) const { return angular_velocity != 0.0 && t >= start; }
  // The angle the frame has turned through by time t [rad].
  double angle(double t) const { return turning(t) ? angular_velocity * (t - start) : 0.0; }
  // Gravity g of the laboratory as seen in the frame at time t.
  NodeVector gravity(const NodeVector& g, double t) const;
  // A direction of the frame at time t, in the laboratory.
  NodeVector to_lab(const NodeVector& v, double t) const;
  // The velocity of the frame's point x relative to the laboratory, omega x (x - c) [m/s].
  NodeVector carried_velocity(const Eigen::Vector2d& x) const;
};

// Adds the centrifugal and Coriolis forces to the nodes heavier than void_node_mass (velocities
// v^{n-1/2} in the frame).
void add_frame_forces(const TurningFrame& frame, const CelGrid& grid, double t,
                      double void_node_mass, NodeFields& nodes);

}  // namespace feedflow::cel
