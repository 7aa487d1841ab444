#pragma once
// Test support: the mass books of a rain-filled run with an outlet sink. Every rained-in sphere
// is in the domain, taken by the sink or trimmed, exactly once (by id), and the masses add up
// to the inserted mass to round-off of the sums.
#include <gtest/gtest.h>

#include <cstdint>
#include <set>

#include "fullsim/dem/dem_engine.hpp"
#include "fullsim/dem/scene/rain_fill.hpp"

namespace feedflow::dem_test {

inline void expect_mass_books_balance(const DemEngine& e, const FillReport& f) {
  const OutletSink& sink = *e.outlet_sink();
  EXPECT_EQ(e.particles().size() + sink.removed_count() + f.trimmed_count, f.inserted_count);
  std::set<std::uint32_t> ids(e.particles().id.begin(), e.particles().id.end());
  for (const auto& ev : sink.events()) EXPECT_TRUE(ids.insert(ev.id).second) << "id twice: " << ev.id;
  EXPECT_EQ(ids.size() + f.trimmed_count, f.inserted_count);
  const double booked = e.particles().total_mass() + sink.removed_mass() + f.trimmed_mass;
  EXPECT_NEAR(booked, f.inserted_mass, 1e-13 * f.inserted_mass);
}

}  // namespace feedflow::dem_test
