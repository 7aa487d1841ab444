#include <gtest/gtest.h>

#include <algorithm>
#include <numbers>
#include <set>
#include <sstream>
#include <tuple>

#include "fullsim/dem/scene/wedge_hopper_slab.hpp"
#include "models/core/errors.hpp"
#include "tests/fullsim/dem/dem_test_scene.hpp"
#include "tests/fullsim/dem/mass_books.hpp"

namespace feedflow {
namespace {

// A small wedge slab (30 deg, 60 mm outlet, 0.12 m bin, 0.1 m fill above the apex) of 3 mm
// spheres, Hertz with the Table 2 friction.
WedgeHopperSlab small_wedge() {
  return WedgeHopperSlab{30.0 * std::numbers::pi / 180.0, 0.06, 0.12, 0.1, 6e-3, 3e-3, 0.3};
}

// The slab `h` with its walls, rain-filled in 5 bands (random seed `seed`, settling capped at
// 0.1 s); the fill's report in `report` if given.
DemEngine filled(const WedgeHopperSlab& h, std::uint64_t seed, FillReport* report = nullptr) {
  DemEngine e(dem_test::pine_twin_settings(), h.box(), ParticleStore{});
  h.add_walls(e);
  std::ostringstream log;
  RainFillSettings rain = h.rain(390.0, 5, seed);
  rain.settle_time_cap = 0.1;
  const FillReport f = rain_fill(e, rain, log);
  if (report) *report = f;
  return e;
}

// Mass bookkeeping: after filling, trimming and 0.25 s of discharge, every inserted sphere is
// either in the domain, booked by the sink or trimmed, exactly once (ids), and the masses add
// up to the inserted mass (same spheres: to the last bits but round-off of the sums).
TEST(WedgeHopperSlab, InsertedEqualsInDomainPlusSinkPlusTrimmed) {
  const WedgeHopperSlab h = small_wedge();
  FillReport f;
  DemEngine e = filled(h, 7, &f);
  e.set_wall_removal_time("gate", e.time());
  e.advance_to(e.time() + 0.25);
  const OutletSink& sink = *e.outlet_sink();
  ASSERT_GT(sink.removed_count(), 20u);  // it discharged
  dem_test::expect_mass_books_balance(e, f);
}

// The fill sits inside the container: no centre closer than R to the wedge (the admits
// predicate), trimmed at the fill top, and the bands count up from the outlet plane.
TEST(WedgeHopperSlab, FillStaysInsideTheWedgeAndIsBanded) {
  const WedgeHopperSlab h = small_wedge();
  const DemEngine e = filled(h, 3);
  const ParticleStore& p = e.particles();
  ASSERT_GT(p.size(), 50u);
  double top_layer = 0.0;
  for (std::size_t k = 0; k < p.size(); ++k) {
    const Vec3& x = p.position[k];
    EXPECT_LE(x.z(), h.fill_top());
    EXPECT_GT(x.z(), 0.0);
    // Distance to the inclined wall, measured along its normal (0.9 R: contact overlap allowed).
    const double inside = (h.half_width(x.z()) - std::abs(x.x())) * std::cos(h.semi_angle);
    EXPECT_GT(inside, 0.9 * h.radius) << "particle " << p.id[k];
    EXPECT_EQ(p.layer[k], std::floor(x.z() / (h.fill_top() / 5)));
    top_layer = std::max(top_layer, p.layer[k]);
  }
  EXPECT_GE(top_layer, 3.0);  // filled up to the upper bands
}

// Geometry of the seed's pilot hopper (data.md 2.1): apex 52 mm below a 60 mm outlet at 30 deg,
// wedge-bin transition at 0.468 m, fill top 0.628 m above the outlet; a 3 mm slab of 3 mm
// spheres is one layer (not periodic).
TEST(WedgeHopperSlab, PilotGeometry) {
  const WedgeHopperSlab h{30.0 * std::numbers::pi / 180.0, 0.06, 0.6, 0.68, 3e-3, 1.5e-3, 0.3};
  EXPECT_NEAR(h.apex_depth(), 0.05196, 1e-5);
  EXPECT_NEAR(h.bin_bottom(), 0.4677, 1e-4);
  EXPECT_NEAR(h.fill_top(), 0.6280, 1e-4);
  EXPECT_FALSE(h.periodic());
}

// The slab faces reach the walls: by default a 3.3 mm pilot slab has frictional front and back
// planes (today's rule), "frictionless" gives the same planes with the frictionless contact set,
// "periodic" a periodic y axis and no planes; periodic faces on a slab thinner than two cutoffs,
// and planar ones on more than one layer, are refused naming dem.slab_faces. One layer (3 mm,
// the seed's): "planar" builds no faces and the engine holds the layer in its mid-plane; the
// default keeps frictional faces and the plan says the free layer presses on them.
TEST(WedgeHopperSlab, SlabFacesChooseTheFrontAndBackWalls) {
  WedgeHopperSlab h{30.0 * std::numbers::pi / 180.0, 0.06, 0.6, 0.68, 3.3e-3, 1.5e-3, 0.3};
  auto faces = [&](SlabFaces f) {
    h.faces = f;
    h.check();
    DemEngine e(dem_test::pine_twin_settings(), h.box(), ParticleStore{});
    h.add_walls(e);
    std::vector<WallContactSet> sets;
    for (const Wall& w : e.walls())
      if (w.name() == "front" || w.name() == "back") sets.push_back(w.contact_set());
    return std::make_tuple(sets, e.box().periodic[1], e.holds_in_plane());
  };
  using Sets = std::vector<WallContactSet>;
  const Sets rough{WallContactSet::particle_wall, WallContactSet::particle_wall};
  const Sets smooth{WallContactSet::frictionless, WallContactSet::frictionless};
  EXPECT_EQ(faces(SlabFaces::automatic), std::make_tuple(rough, false, false));
  EXPECT_EQ(faces(SlabFaces::frictional), std::make_tuple(rough, false, false));
  EXPECT_EQ(faces(SlabFaces::frictionless), std::make_tuple(smooth, false, false));
  EXPECT_NE(h.describe().find("frictionless front and back planes"), std::string::npos);
  try {
    faces(SlabFaces::periodic);
    FAIL() << "a periodic 3.3 mm slab of 1.5 mm spheres was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("dem.slab_faces"), std::string::npos) << e.what();
  }
  try {
    faces(SlabFaces::planar);
    FAIL() << "a planar 3.3 mm slab of 1.5 mm spheres (not one layer) was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("dem.slab_faces"), std::string::npos) << e.what();
  }
  h.depth = 3e-3;
  EXPECT_EQ(faces(SlabFaces::planar), std::make_tuple(Sets{}, false, true));
  EXPECT_EQ(faces(SlabFaces::automatic), std::make_tuple(rough, false, false));
  EXPECT_NE(h.describe_faces().find("buckles"), std::string::npos) << h.describe_faces();
  h.depth = 12e-3;
  EXPECT_EQ(faces(SlabFaces::periodic), std::make_tuple(Sets{}, true, false));
  EXPECT_EQ(faces(SlabFaces::automatic), std::make_tuple(Sets{}, true, false));
  EXPECT_EQ(faces(SlabFaces::frictionless), std::make_tuple(smooth, false, false));
}

// The held layer through a fill and 0.1 s of discharge: every centre stays in the mid-plane
// to the bit, so nothing ever crossed the slab.
TEST(WedgeHopperSlab, HeldLayerStaysInTheMidPlaneThroughFillAndDischarge) {
  WedgeHopperSlab h = small_wedge();  // 6 mm slab of 3 mm spheres: one layer
  h.faces = SlabFaces::planar;
  DemEngine e = filled(h, 7);
  const ParticleStore& p = e.particles();
  ASSERT_GT(p.size(), 50u);
  for (std::size_t k = 0; k < p.size(); ++k) EXPECT_EQ(p.position[k].y(), 0.5 * h.depth);
  e.set_wall_removal_time("gate", e.time());
  e.advance_to(e.time() + 0.1);
  for (std::size_t k = 0; k < p.size(); ++k) EXPECT_EQ(p.position[k].y(), 0.5 * h.depth);
  ASSERT_GT(e.outlet_sink()->removed_count(), 20u);  // it flowed
}

}  // namespace
}  // namespace feedflow
