// Contact-kernel evaluations per second (items/s): one composed law over 4096 contacts with
// their history arrays, inputs varied so branches and the Coulomb/rolling caps are exercised.
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "models/contact/contact_law_registry.hpp"
#include "tests/support/pine_table2.hpp"

namespace {

using namespace feedflow;

DemContactParameters pine_contact() { return testing::pine_table2_particle_particle(); }  // seed Table 2, P-P

std::vector<ContactInput> contacts(std::size_t n) {
  std::vector<ContactInput> in(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double s = std::sin(0.37 * static_cast<double>(i));
    ContactInput& c = in[i];
    c.overlap = 1e-5 + 1e-4 * (0.5 + 0.5 * s);
    c.normal = Vec3(s, 0.3, 1.0).normalized();
    c.normal_velocity = 1e-2 * std::cos(0.11 * static_cast<double>(i));
    c.tangential_velocity = Vec3(1e-2 * s, -5e-3, 0.0);
    c.tangential_velocity -= c.tangential_velocity.dot(c.normal) * c.normal;
    c.relative_angular_velocity = Vec3(3.0 * s, 1.0, -2.0);
    c.effective_radius = 0.75e-3;
    c.effective_mass = 2.76e-6;
    c.effective_inertia = 1.2e-12;
    c.dt = 1e-6;
  }
  return in;
}

template <class Law>
void evaluate_contacts(benchmark::State& state) {
  const Law law(pine_contact());
  const auto in = contacts(4096);
  std::vector<typename Law::History> history(in.size(), typename Law::History{});
  for (auto _ : state) {
    Vec3 sum = Vec3::Zero();
    for (std::size_t i = 0; i < in.size(); ++i) {
      const ContactOutput out = law.evaluate(in[i], history[i]);
      sum += out.normal_force * in[i].normal + out.tangential_force + out.rolling_torque;
    }
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<long>(in.size()));
}

using HertzMindlinCdt =
    ContactLaw<HertzNormal, TangentialHistory<MindlinStiffness>, RollingCdt, NoCohesion>;
using HystereticHistoryCdt = ContactLaw<HystereticNonlinear2,
                                        TangentialHistory<HandedOnStiffness>, RollingCdt,
                                        NoCohesion>;
using HystereticHistoryEpsd2 = ContactLaw<HystereticNonlinear2,
                                          TangentialHistory<HandedOnStiffness>, RollingEpsd2,
                                          NoCohesion>;

void ContactHertzMindlinCdt(benchmark::State& s) { evaluate_contacts<HertzMindlinCdt>(s); }
void ContactHystereticNonlinear2HistoryCdt(benchmark::State& s) {
  evaluate_contacts<HystereticHistoryCdt>(s);
}
void ContactHystereticNonlinear2HistoryEpsd2(benchmark::State& s) {
  evaluate_contacts<HystereticHistoryEpsd2>(s);
}
BENCHMARK(ContactHertzMindlinCdt);
BENCHMARK(ContactHystereticNonlinear2HistoryCdt);
BENCHMARK(ContactHystereticNonlinear2HistoryEpsd2);

}  // namespace
