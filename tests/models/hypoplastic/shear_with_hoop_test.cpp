// The pine law (seed Table 1) sheared with a hoop compression, as a cone's wall band is (issue
// 22): with its in-plane normal stresses held (mixed control), it dilates to the critical state
// whatever the hoop rate. The CEL cone's wall band stays dense (tests/benchmarks/RECORD.md,
// axisymmetric CEL-FEM); this test is the law's side of that comparison.
#include <gtest/gtest.h>

#include <cstdio>

#include "models/hypoplastic/mixed_control.hpp"

namespace feedflow {
namespace {

// Simple shear D_xy = 0.5 /s with spin, T_xx and T_yy held, hoop rate D_zz = -kappa (kappa = 0 ...
// 0.5 of the shear rate), from the dense state the settled fill reaches (e = 0.645) at a few
// hundred pascals, to a shear strain of 2: e rises above 0.8 (measured 0.840 ... 0.824, against
// e_c = 0.83 at this pressure) and T_zz / T_xx stays below 2.5 (measured 1.13 ... 2.33).
TEST(HypoplasticShearWithHoop, DilatesToCriticalUnderHoopCompression) {
  const HypoplasticModel model = make_hypoplastic_model(loblolly_pine_table1());
  for (double kappa : {0.0, 0.2, 0.5}) {
    ElementControl control;
    control.control = {ComponentControl::stress, ComponentControl::stress, ComponentControl::strain,
                       ComponentControl::strain, ComponentControl::strain, ComponentControl::strain};
    control.rate = {0.0, 0.0, -kappa, 0.5, 0.0, 0.0};
    control.spin(0, 1) = 0.5;
    control.spin(1, 0) = -0.5;
    const MixedControlSolver solver(model, control);
    MaterialPointState s{Eigen::Vector3d(-400.0, -500.0, -400.0).asDiagonal(), 0.645};
    const double dt = 2e-4;  // explicit Euler on the exact rates, 10 000 steps to gamma = 2
    for (int k = 0; k < 10000; ++k) {
      const ElementRates r = solver.solve(s);
      s.stress += dt * r.stress_rate;
      s.void_ratio += dt * (1.0 + s.void_ratio) * r.stretching.trace();
    }
    std::printf("kappa %.1f: e %.3f, T_zz / T_xx %.2f\n", kappa, s.void_ratio, s.stress(2, 2) / s.stress(0, 0));
    EXPECT_GT(s.void_ratio, 0.80);
    EXPECT_LT(s.stress(2, 2) / s.stress(0, 0), 2.5);
  }
}

}  // namespace
}  // namespace feedflow
