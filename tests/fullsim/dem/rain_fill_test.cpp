#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <functional>
#include <sstream>

#include "fullsim/dem/scene/rain_fill.hpp"
#include "models/os/interrupt_request.hpp"
#include "tests/fullsim/dem/dem_test_scene.hpp"

namespace feedflow {
namespace {

using namespace dem_test;

// A 30 x 12 mm floor (periodic in y) and a rain region 20 mm above it; 150 spheres.
struct RainBox {
  DemEngine engine;
  RainFillSettings fill;
};

RainBox make_rain_box(std::uint64_t seed) {
  DemSettings s = hertz_settings(0.3, 0.5, 0.0);
  const Vec3 lower(0, 0, 0), upper(0.03, 0.012, 0.06);
  RainBox b{DemEngine(s, SimulationBox{lower, upper, {false, true, false}}, ParticleStore{}), {}};
  b.engine.add_wall(Wall::plane("floor", lower, Vec3::UnitZ()));
  b.engine.add_wall(Wall::plane("x-", lower, Vec3::UnitX()));
  b.engine.add_wall(Wall::plane("x+", upper, -Vec3::UnitX()));
  RainFillSettings& f = b.fill;
  f.region_lower = Vec3(0.0, 0.0, 0.02);
  f.region_upper = Vec3(0.03, 0.012, 0.03);
  f.radius = kRadius;
  f.density = kDensity;
  const double m = kDensity * 4.0 / 3.0 * 3.14159265358979 * kRadius * kRadius * kRadius;
  f.mass_rate = 1500 * m;  // 150 spheres in 0.1 s
  f.target_count = 150;
  f.initial_velocity = Vec3(0, 0, -0.3);
  f.settle_speed = 5e-3;
  f.settle_time_cap = 0.3;
  f.trim_height = 0.006;
  f.band_height = 0.002;
  f.seed = seed;
  return b;
}

double deepest_overlap(const ParticleStore& p, const SimulationBox& box) {
  double deepest = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j) {
      const double d = box.minimum_image(p.position[i] - p.position[j]).norm();
      deepest = std::max(deepest, p.radius[i] + p.radius[j] - d);
    }
  return deepest;
}

// Every sphere is placed where it overlaps no particle (minimum image across the periodic
// axis) and no wall, inside the region, with the asked initial velocity.
TEST(RainFill, InsertsWithoutOverlapsInsideTheRegion) {
  RainBox b = make_rain_box(3);
  std::ostringstream log;
  b.fill.target_count = 60;  // one batch: nothing has moved yet when it is checked
  b.fill.mass_rate *= 100.0;
  b.fill.settle_time_cap = 0.0;
  b.fill.settle_check_interval = 1e-9;
  b.fill.trim_height.reset();
  rain_fill(b.engine, b.fill, log);
  const ParticleStore& p = b.engine.particles();
  ASSERT_EQ(p.size(), 60u);
  EXPECT_LE(deepest_overlap(p, b.engine.box()), 1e-6 * kRadius);
  for (std::size_t k = 0; k < p.size(); ++k) {
    EXPECT_GE(p.position[k].z(), 0.02 - 1e-3);
    EXPECT_LE(p.position[k].z(), 0.03);
    EXPECT_GE(p.position[k].x(), kRadius);
    EXPECT_LE(p.position[k].x(), 0.03 - kRadius);
  }
}

// The whole fill (rain, settle, trim, bands) is deterministic for a seed and differs for
// another seed; mass is booked: kept + trimmed = inserted; bands follow the settled height.
TEST(RainFill, DeterministicForASeedAndBooksTheTrimmedMass) {
  std::ostringstream log;
  RainBox a = make_rain_box(11), b = make_rain_box(11), c = make_rain_box(12);
  const FillReport ra = rain_fill(a.engine, a.fill, log);
  const FillReport rb = rain_fill(b.engine, b.fill, log);
  rain_fill(c.engine, c.fill, log);
  ASSERT_EQ(ra.inserted_count, 150u);
  EXPECT_TRUE(ra.target_reached);
  EXPECT_GT(ra.trimmed_count, 0u);
  EXPECT_EQ(a.engine.particles().position, b.engine.particles().position);
  EXPECT_EQ(ra.trimmed_count, rb.trimmed_count);
  EXPECT_NE(a.engine.particles().position, c.engine.particles().position);
  EXPECT_NEAR(a.engine.particles().total_mass() + ra.trimmed_mass, ra.inserted_mass,
              1e-12 * ra.inserted_mass);
  const ParticleStore& p = a.engine.particles();
  for (std::size_t k = 0; k < p.size(); ++k) {
    EXPECT_LE(p.position[k].z(), 0.006);
    EXPECT_EQ(p.layer[k], std::floor(p.position[k].z() / 0.002));
  }
  EXPECT_LT(deepest_overlap(p, a.engine.box()), 0.1 * kRadius);  // a settled bed, no blow-up
}

class CountingProgress final : public ProgressSink {
 public:
  explicit CountingProgress(std::function<void(int updates, bool finished)> hook) : hook_(std::move(hook)) {}
  void begin(const std::string&, double, const std::string&) override {}
  void update(double) override { hook_(++updates_, false); }
  void finish() override { hook_(updates_, true); }

 private:
  std::function<void(int, bool)> hook_;
  int updates_ = 0;
};

struct Stop {
  const char* where;
  int placement_try = 0;    // Ctrl-C at this try of a placement (0: not)
  int progress_update = 0;  // at this progress update, between batches (0: not)
  bool settling = false;    // once the insertion has finished
};

// A fill stopped by Ctrl-C inside a batch, between batches or while settling, saved with the
// engine's checkpoint and continued in a new engine, ends with the same particles bit for bit
// as one uninterrupted fill; stopped inside its first batch there is nothing to save.
TEST(RainFill, ContinuedFromItsCheckpointGivesTheSameBits) {
  std::ostringstream log;
  RainBox straight = make_rain_box(5);
  const FillReport whole = rain_fill(straight.engine, straight.fill, log);
  const auto file = std::filesystem::temp_directory_path() / ("feedflow_fill_" + std::to_string(::getpid()) + ".h5");
  int saved = 0, inside_a_batch = 0;
  for (const Stop stop : {Stop{"first batch", 5}, Stop{"a later batch", 150}, Stop{"a later batch", 333},
                          Stop{"between batches", 0, 4}, Stop{"settling", 0, 0, true}}) {
    RainBox cut = make_rain_box(5);
    int tries = 0;
    const auto admits = cut.fill.admits;
    cut.fill.admits = [&](const Vec3&, double) {
      if (++tries == stop.placement_try) request_interrupt();
      return true;
    };
    CountingProgress progress([&](int updates, bool finished) {
      if ((stop.progress_update && updates == stop.progress_update) || (stop.settling && finished))
        request_interrupt();
    });
    cut.fill.progress = &progress;
    RainFill fill(cut.fill);
    const FillReport stopped = fill.run(cut.engine, log);
    clear_interrupt_request();
    ASSERT_TRUE(stopped.interrupted) << stop.where;
    bool written = false;
    {
      Hdf5File f(file, Hdf5File::Mode::create);
      written = fill.save(cut.engine, f);
    }
    if (std::string(stop.where) == "first batch") {
      EXPECT_FALSE(written) << "nothing to continue inside the first batch";
      continue;
    }
    ASSERT_TRUE(written) << stop.where;
    ++saved;
    if (Hdf5File(file, Hdf5File::Mode::read).dims("/fill/placed").at(0) > 0) ++inside_a_batch;
    RainBox again = make_rain_box(5);
    RainFill rest(again.fill);
    rest.restore(again.engine, Hdf5File(file, Hdf5File::Mode::read));
    const FillReport r = rest.run(again.engine, log);
    EXPECT_FALSE(r.interrupted);
    EXPECT_EQ(r.inserted_count, whole.inserted_count) << stop.where;
    EXPECT_EQ(r.trimmed_count, whole.trimmed_count) << stop.where;
    EXPECT_EQ(r.end_time, whole.end_time) << stop.where;
    EXPECT_EQ(again.engine.particles().position, straight.engine.particles().position) << stop.where;
    EXPECT_EQ(again.engine.particles().velocity, straight.engine.particles().velocity) << stop.where;
  }
  std::filesystem::remove(file);
  EXPECT_EQ(saved, 4);
  EXPECT_GE(inside_a_batch, 1);  // the state of a batch half placed was saved and continued
}

// A file without a fill under way is refused by name.
TEST(RainFill, RestoreRefusesAFileWithoutAFill) {
  RainBox b = make_rain_box(5);
  const auto file = std::filesystem::temp_directory_path() / ("feedflow_nofill_" + std::to_string(::getpid()) + ".h5");
  { Hdf5File f(file, Hdf5File::Mode::create); }
  RainFill fill(b.fill);
  EXPECT_FALSE(RainFill::saved_in(Hdf5File(file, Hdf5File::Mode::read)));
  EXPECT_THROW(fill.restore(b.engine, Hdf5File(file, Hdf5File::Mode::read)), std::runtime_error);
  std::filesystem::remove(file);
}

// A region that follows the fill rides above the resting particles.
TEST(RainFill, RestingFillTopIgnoresFallingParticles) {
  ParticleStore p;
  p.add(Vec3(0, 0, 0.01), kRadius, kDensity);
  p.add(Vec3(0, 0, 0.05), kRadius, kDensity, 0.0, Vec3(0, 0, -1.0));
  EXPECT_DOUBLE_EQ(resting_fill_top(BedView(p, p.size(), DemRanks::one()), 0.2), 0.01);
}

}  // namespace
}  // namespace feedflow
