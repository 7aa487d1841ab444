#include "models/hypoplastic/stress_invariants.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <numbers>

namespace feedflow {

double mean_pressure(const Eigen::Matrix3d& stress) { return -stress.trace() / 3.0; }

double deviatoric_stress(const Eigen::Matrix3d& stress) {
  Eigen::Matrix3d s = stress;
  s.diagonal().array() -= stress.trace() / 3.0;
  return std::sqrt(1.5 * s.cwiseAbs2().sum());
}

double mobilised_friction_angle(const Eigen::Matrix3d& stress) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
  eigen.computeDirect(-stress, Eigen::EigenvaluesOnly);
  const double s3 = eigen.eigenvalues()(0), s1 = eigen.eigenvalues()(2);  // ascending
  if (!(s3 > 0.0)) return std::numbers::pi / 2;
  return std::asin((s1 - s3) / (s1 + s3));
}

}  // namespace feedflow
