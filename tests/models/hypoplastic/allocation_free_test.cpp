// The per-cell routine allocates nothing: global operator new is counted around 1000 steps.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "models/hypoplastic/element_tests.hpp"
#include "models/hypoplastic/material_point_integrator.hpp"

namespace {
std::atomic<long> g_allocations{0};
}

void* operator new(std::size_t size) {
  ++g_allocations;
  if (void* p = std::malloc(size ? size : 1)) return p;
  throw std::bad_alloc();
}
// GCC 12 at -O1 takes the free() below for one of a pointer from the built-in operator new
// (-Wmismatched-new-delete); both operators are replaced here, so the pair matches.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
#pragma GCC diagnostic pop

namespace feedflow {
namespace {

// 1000 integrated material-point steps (with spin and substepping) make no heap allocation.
TEST(HypoplasticIntegrator, AllocationFree) {
  const auto m = make_hypoplastic_model(loblolly_pine_table1());
  MaterialPointState s = isotropic_state(2e3, 0.8);
  Eigen::Matrix3d d, w = Eigen::Matrix3d::Zero();
  d << -1.0, 0.3, 0.0, 0.3, 0.2, 0.0, 0.0, 0.0, 0.1;
  w(0, 1) = 0.3;
  w(1, 0) = -0.3;
  const long before = g_allocations.load();
  for (int i = 0; i < 1000; ++i) integrate_material_point(m, s, d, w, i % 10 ? 5e-5 : 1e-3);
  EXPECT_EQ(g_allocations.load() - before, 0);
  EXPECT_TRUE(s.stress.allFinite());
}

}  // namespace
}  // namespace feedflow
