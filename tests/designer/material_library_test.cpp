// Materials: the built-in loblolly pine carries the seed's Tables 1 and 2 with sources; broken
// material files are refused with file, line and key.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "designer/case/material_library.hpp"
#include "designer/design/case_inputs.hpp"
#include "models/core/errors.hpp"
#include "models/units/angle.hpp"

namespace fs = std::filesystem;

namespace feedflow {
namespace {

// The compiled-in pine (no folders searched) holds seed Table 1, Table 2 and the bulk data.
TEST(MaterialLibrary, BuiltInPineHoldsSeedTables) {
  const Material m = MaterialLibrary({}).load("loblolly_pine");
  EXPECT_EQ(m.origin, "built-in");
  EXPECT_NEAR(m.bulk.density, 290.0, 1e-12);
  EXPECT_NEAR(*m.bulk.loose_density, 182.0, 1e-12);
  EXPECT_NEAR(m.bulk.wall_friction_angle, 8.5 * kDegree, 1e-12);
  EXPECT_NEAR(*m.bulk.moisture_content, 0.06, 1e-12);
  EXPECT_NEAR(m.psd->d10, 0.38e-3, 1e-15);
  EXPECT_NEAR(m.psd->d50, 0.82e-3, 1e-15);
  EXPECT_NEAR(m.psd->d90, 1.79e-3, 1e-15);
  const auto& hp = *m.hypoplastic;  // Table 1
  EXPECT_NEAR(hp.phi_c, 47.3 * kDegree, 1e-12);
  EXPECT_NEAR(hp.h_s, 187.6e3, 1e-9);
  EXPECT_NEAR(hp.n, 0.30, 1e-12);
  EXPECT_NEAR(hp.e_d0, 0.50, 1e-12);
  EXPECT_NEAR(hp.e_c0, 1.06, 1e-12);
  EXPECT_NEAR(hp.e_i0, 1.38, 1e-12);
  EXPECT_NEAR(hp.alpha, 0.3, 1e-12);
  EXPECT_NEAR(hp.beta, 1.0, 1e-12);
  const auto& dem = *m.dem;  // Table 2
  EXPECT_NEAR(dem.particle.radius, 1.5e-3, 1e-15);
  EXPECT_NEAR(dem.particle.density, 390.0, 1e-12);
  for (const auto* c : {&dem.particle_particle, &dem.particle_wall}) {
    EXPECT_NEAR(c->alpha_prime, 20.0, 1e-12);
    EXPECT_NEAR(c->chi, 2.0, 1e-12);
    EXPECT_NEAR(c->a1, 6e8, 1e-3);
    EXPECT_NEAR(c->a2, 5e4, 1e-9);
    EXPECT_NEAR(c->a3, 5.0, 1e-12);
    EXPECT_NEAR(c->k_nc, 1e-4, 1e-18);
    EXPECT_NEAR(c->c, 1e-7, 1e-20);
    EXPECT_NEAR(c->youngs_modulus, 1e6, 1e-6);
    EXPECT_NEAR(c->poisson_ratio, 0.3, 1e-12);
    EXPECT_NEAR(c->restitution, 0.3, 1e-12);
  }
  EXPECT_NEAR(dem.particle_particle.friction, 0.5, 1e-12);
  EXPECT_NEAR(dem.particle_wall.friction, 0.2, 1e-12);
  EXPECT_NEAR(dem.particle_particle.rolling_friction, 0.8, 1e-12);
  EXPECT_NEAR(dem.particle_wall.rolling_friction, 0.6, 1e-12);
}

// Every listed parameter of the pine has a unit in its display text and a stated source.
TEST(MaterialLibrary, EveryPineParameterHasASource) {
  const auto params = material_parameters(MaterialLibrary({}).load("loblolly_pine"));
  EXPECT_EQ(params.size(), 4u + 3u + 8u + 9u + 9u + 7u + 2u + 12u + 12u);  // FF lists are empty for a linear FF
  for (const auto& p : params) {
    SCOPED_TRACE(p.value.key);
    EXPECT_NE(p.value.source, "unknown");
    EXPECT_FALSE(p.value.source.empty());
    EXPECT_FALSE(p.description.empty());
  }
}

// The shipped file and the compiled-in text are the same material.
TEST(MaterialLibrary, ShippedFileMatchesBuiltIn) {
  const Material file = MaterialLibrary({"cases/materials"}).load("loblolly_pine");
  const Material builtin = MaterialLibrary({}).load("loblolly_pine");
  EXPECT_NE(file.origin, "built-in");
  EXPECT_EQ(file.sources, builtin.sources);
  EXPECT_EQ(file.hypoplastic->e_i0, builtin.hypoplastic->e_i0);
  const auto names = MaterialLibrary::standard().list();
  ASSERT_FALSE(names.empty());
  EXPECT_EQ(names.front().name, "loblolly_pine");
}

// A user material file with an inconsistent hypoplastic set is refused at the key's line.
TEST(MaterialLibrary, BrokenUserMaterialNamesFileLineKey) {
  const fs::path dir = fs::temp_directory_path() / "feedflow_material_test";
  fs::create_directories(dir);
  std::ofstream(dir / "bad.toml") << "name = \"bad\"\n[bulk]\ndensity = \"300 kg/m^3\"\n"
                                     "wall_friction_angle = \"10 deg\"\n[hypoplastic]\n"
                                     "phi_c = \"30 deg\"\nh_s = \"1 MPa\"\nn = 0.3\ne_d0 = 0.6\n"
                                     "e_c0 = 0.5\ne_i0 = 1.2\nalpha = 0.1\nbeta = 1\n";
  try {
    MaterialLibrary({dir}).load("bad");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("bad.toml:10"), std::string::npos) << m;
    EXPECT_NE(m.find("hypoplastic.e_c0"), std::string::npos) << m;
    EXPECT_NE(m.find("must exceed e_d0"), std::string::npos) << m;
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace feedflow
