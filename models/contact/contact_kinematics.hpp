#pragma once
// What a contact-law kernel sees of one contact and what it returns (models.md 4.1, LIGGGHTS
// convention): the normal n points from body j to body i, the overlap is positive in contact,
// the normal velocity is positive when the bodies separate. Forces and torques are those on
// body i; body j receives their opposites (the rolling torque too). For a wall, j is the wall.
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace feedflow {

using Vec3 = Eigen::Vector3d;

struct ContactInput {
  double overlap = 0.0;                          // delta = R_i + R_j - |x_i - x_j| [m]
  Vec3 normal = Vec3::UnitZ();                   // unit normal from j to i [-]
  double normal_velocity = 0.0;                  // v_n = (v_i - v_j).n, > 0 separating [m/s]
  Vec3 tangential_velocity = Vec3::Zero();       // slip velocity of the contact point [m/s]
  Vec3 relative_angular_velocity = Vec3::Zero(); // omega_i - omega_j (wall: its own) [rad/s]
  double effective_radius = 0.0;                 // R* = R_i R_j/(R_i + R_j); wall: R_i [m]
  double effective_mass = 0.0;                   // m* = m_i m_j/(m_i + m_j); wall or frozen j: m_i [kg]
  double effective_inertia = 0.0;                // (1/I_i + 1/I_j)^-1; wall: I_i [kg m^2]
  double dt = 0.0;                               // time step [s]
};

struct ContactOutput {
  double normal_force = 0.0;                // F_n along n on body i [N]
  Vec3 tangential_force = Vec3::Zero();     // on body i, in the contact plane [N]
  Vec3 rolling_torque = Vec3::Zero();       // rolling resistance torque on body i [N m]
};

// The stiffest springs of one contact in its current state, for the stable time step.
struct ContactStiffness {
  double normal = 0.0;      // largest of the loading and unloading slopes dF_n/d delta [N/m]
  double tangential = 0.0;  // k_t [N/m]
  double rolling = 0.0;     // k_r [N m/rad]; zero for the constant-torque laws
};

// a.b and |a|^2 summed as (x + y) + z, the order of Eigen's SSE reduction, written out: the
// pair loop's batches are built with Eigen's own SSE code off (its intrinsics stop the
// vectoriser), and its plain reduction would sum x + (y + z), other bits than elsewhere.
inline double dot(const Vec3& a, const Vec3& b) {
  return (a.x() * b.x() + a.y() * b.y()) + a.z() * b.z();
}
inline double squared_norm(const Vec3& a) { return dot(a, a); }
// a where c holds, else b, component by component: a select rather than a branch, so that a
// law evaluated over a batch of contacts compiles to one vector loop.
inline Vec3 select(bool c, const Vec3& a, const Vec3& b) {
  return Vec3(c ? a.x() : b.x(), c ? a.y() : b.y(), c ? a.z() : b.z());
}
// Effective moduli of two bodies of the same material (particle-wall contacts use the P-W
// parameter set for both sides): 1/E* = 2(1 - nu^2)/E, 1/G* = 2 (2 - nu)(1 + nu)/E (models.md 4.2).
inline double effective_youngs_modulus(double youngs_modulus, double poisson_ratio) {
  return youngs_modulus / (2.0 * (1.0 - poisson_ratio * poisson_ratio));
}
inline double effective_shear_modulus(double youngs_modulus, double poisson_ratio) {
  return youngs_modulus / (4.0 * (2.0 - poisson_ratio) * (1.0 + poisson_ratio));
}

}  // namespace feedflow
