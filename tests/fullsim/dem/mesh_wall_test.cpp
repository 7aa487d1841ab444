// Triangle-mesh walls: the STL reader and sphere-mesh contact against the analytic walls.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

#include "fullsim/dem/mesh_wall.hpp"
#include "fullsim/dem/scene/sawtooth_ramp.hpp"
#include "fullsim/dem/stl_file.hpp"
#include "models/core/errors.hpp"
#include "tests/fullsim/dem/dem_test_scene.hpp"

namespace feedflow {
namespace {

using namespace dem_test;
namespace fs = std::filesystem;

using Corners = std::array<Vec3, 3>;

fs::path temp_dir() {
  const fs::path d = fs::temp_directory_path() / ("feedflow_stl_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}

void write_ascii(const fs::path& path, const std::vector<Corners>& tris) {
  std::ofstream f(path);
  f << "solid test\n";
  for (const auto& t : tris) {
    f << "  facet normal 0 0 1\n    outer loop\n";
    for (const auto& v : t) f << "      vertex " << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
    f << "    endloop\n  endfacet\n";
  }
  f << "endsolid test\n";
}

void write_binary(const fs::path& path, const std::vector<Corners>& tris) {
  std::ofstream f(path, std::ios::binary);
  char header[80] = {};
  std::memcpy(header, "solid but binary", 16);  // a binary header may start with "solid"
  f.write(header, 80);
  const auto n = static_cast<std::uint32_t>(tris.size());
  f.write(reinterpret_cast<const char*>(&n), 4);
  for (const auto& t : tris) {
    float v[12] = {0, 0, 1};
    for (int k = 0; k < 3; ++k)
      for (int a = 0; a < 3; ++a) v[3 + 3 * k + a] = static_cast<float>(t[k][a]);
    f.write(reinterpret_cast<const char*>(v), sizeof v);
    const std::uint16_t attr = 0;
    f.write(reinterpret_cast<const char*>(&attr), 2);
  }
}

// A square [0, n s]^2 in the plane z = 0 split into 2 n^2 triangles (alternating diagonals, so
// grid nodes are shared by 4, 6 or 8 triangles).
std::vector<Corners> square_plane(int n, double s) {
  std::vector<Corners> out;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const Vec3 a(i * s, j * s, 0), b((i + 1) * s, j * s, 0), c((i + 1) * s, (j + 1) * s, 0),
          d(i * s, (j + 1) * s, 0);
      if ((i + j) % 2 == 0) {
        out.push_back({a, b, c});
        out.push_back({a, c, d});
      } else {
        out.push_back({a, b, d});
        out.push_back({b, c, d});
      }
    }
  return out;
}

TriangleMesh mesh_of(const std::vector<Corners>& tris) {
  TriangleMesh m;
  for (std::size_t t = 0; t < tris.size(); ++t) m.add_triangle(tris[t][0], tris[t][1], tris[t][2], t);
  m.source = "test";
  return m;
}

std::string error_of(const fs::path& path) {
  try {
    read_stl(path.string(), 1e-3);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// Binary (header starting with "solid") and ASCII files of the same 8 triangles in mm read to
// the same welded mesh: 9 vertices, 8 triangles, coordinates scaled to metres.
TEST(StlFile, BinaryAndAsciiReadToTheSameMesh) {
  const fs::path dir = temp_dir();
  const auto tris = square_plane(2, 2.5);
  write_ascii(dir / "a.stl", tris);
  write_binary(dir / "b.stl", tris);
  const TriangleMesh a = read_stl((dir / "a.stl").string(), 1e-3);
  const TriangleMesh b = read_stl((dir / "b.stl").string(), 1e-3);
  EXPECT_EQ(a.triangles.size(), 8u);
  EXPECT_EQ(a.vertices.size(), 9u);
  EXPECT_EQ(a.triangles, b.triangles);
  ASSERT_EQ(a.vertices.size(), b.vertices.size());
  for (std::size_t i = 0; i < a.vertices.size(); ++i) EXPECT_EQ(a.vertices[i], b.vertices[i]);
  EXPECT_DOUBLE_EQ(a.vertices.back().x(), 5e-3);
  EXPECT_TRUE(a.degenerate.empty());
  fs::remove_all(dir);
}

// Malformed files are refused naming the file and the fault; a degenerate triangle is dropped
// and listed.
TEST(StlFile, MalformedFilesAreRefusedClearly) {
  const fs::path dir = temp_dir();
  const auto tris = square_plane(1, 1.0);
  write_binary(dir / "cut.stl", tris);
  fs::resize_file(dir / "cut.stl", 84 + 50 + 20);  // header says 2 triangles
  const std::string cut = error_of(dir / "cut.stl");
  EXPECT_NE(cut.find("cut.stl"), std::string::npos) << cut;
  EXPECT_NE(cut.find("header gives 2 triangles"), std::string::npos) << cut;

  write_ascii(dir / "nan.stl", tris);
  {
    std::ifstream in(dir / "nan.stl");
    std::stringstream s;
    s << in.rdbuf();
    std::string text = s.str();
    text.replace(text.find("vertex 1 0 0"), 12, "vertex 1 nan 0");
    std::ofstream(dir / "nan.stl") << text;
  }
  const std::string nan = error_of(dir / "nan.stl");
  EXPECT_NE(nan.find("non-finite vertex"), std::string::npos) << nan;

  write_ascii(dir / "short.stl", tris);
  fs::resize_file(dir / "short.stl", fs::file_size(dir / "short.stl") - 30);
  const std::string trunc = error_of(dir / "short.stl");
  EXPECT_NE(trunc.find("truncated"), std::string::npos) << trunc;

  std::ofstream(dir / "tiny.stl") << "abc";
  EXPECT_NE(error_of(dir / "tiny.stl").find("truncated"), std::string::npos);

  auto with_flat = tris;
  with_flat.push_back({Vec3(0, 0, 0), Vec3(1, 1, 0), Vec3(2, 2, 0)});  // collinear
  write_ascii(dir / "flat.stl", with_flat);
  const TriangleMesh m = read_stl((dir / "flat.stl").string(), 1.0);
  EXPECT_EQ(m.triangles.size(), 2u);
  ASSERT_EQ(m.degenerate.size(), 1u);
  EXPECT_EQ(m.degenerate[0], 2u);
  fs::remove_all(dir);
}

struct Trajectory {
  std::vector<Vec3> x, w;
};

// Runs one sphere from x0 with velocity v0 for `steps`, on an analytic floor or on the
// triangulated floor, recording position and spin every step.
Trajectory run(bool mesh, const Vec3& x0, const Vec3& v0, long steps) {
  DemSettings s = hertz_settings(0.3, 0.5, 0.0);
  ParticleStore p;
  p.add(x0, kRadius, kDensity, 0.0, v0);
  SimulationBox box{Vec3(-0.01, -0.01, -0.01), Vec3(0.03, 0.03, 0.03), {false, false, false}};
  DemEngine e(s, box, p);
  if (mesh)
    e.add_mesh_wall(MeshWall("floor", mesh_of(square_plane(8, 2e-3))));
  else
    e.add_wall(Wall::plane("floor", Vec3::Zero(), Vec3::UnitZ()));
  std::ostringstream plan;
  e.prepare(plan);
  Trajectory t;
  for (long k = 0; k < steps; ++k) {
    e.run_steps(1);
    t.x.push_back(e.particles().position[0]);
    t.w.push_back(e.particles().angular_velocity[0]);
  }
  return t;
}

double largest_difference(const Trajectory& a, const Trajectory& b) {
  double d = 0.0;
  for (std::size_t k = 0; k < a.x.size(); ++k) d = std::max(d, (a.x[k] - b.x[k]).norm());
  return d;
}

// Dropped on a face, on an edge (a diagonal and a grid line) and on a node shared by 8
// triangles, the sphere follows the analytic-plane trajectory to 1e-9 of its radius (bounce and
// rest; a doubled edge or vertex contact would halve the rest overlap).
TEST(MeshWall, DropOnTriangulatedPlaneMovesAsOnTheAnalyticPlane) {
  const Vec3 spots[] = {{5.3e-3, 6.6e-3, 0}, {5e-3, 5e-3 + 1e-3, 0},
                        {6e-3, 6e-3, 0}, {4e-3, 4e-3, 0}, {3e-3, 3e-3, 0}};
  for (const Vec3& spot : spots) {
    const Vec3 x0 = spot + Vec3(0, 0, 2.5e-3);
    const Trajectory plane = run(false, x0, Vec3::Zero(), 6000);
    const Trajectory mesh = run(true, x0, Vec3::Zero(), 6000);
    const double d = largest_difference(plane, mesh);
    std::printf("drop at (%.1f, %.1f) mm: rest overlap %.4g m, largest difference %.3g m\n",
                spot.x() * 1e3, spot.y() * 1e3, kRadius - plane.x.back().z(), d);
    EXPECT_GT(kRadius - plane.x.back().z(), 0.0);  // it landed
    EXPECT_LE(d, 1e-9 * kRadius);
  }
}

// A sphere sliding and rolling diagonally across many edges and nodes of the triangulated
// plane keeps the analytic trajectory (position and spin): the normal force neither doubles
// nor jumps at an edge and the tangential history carries over to the next triangle.
TEST(MeshWall, SphereSlidingAcrossEdgesFollowsTheAnalyticPlane) {
  const Vec3 x0(1e-3, 1.5e-3, kRadius - 1e-6);
  const Vec3 v0(0.08, 0.05, 0.0);
  const Trajectory plane = run(false, x0, v0, 8000);
  const Trajectory mesh = run(true, x0, v0, 8000);
  const double d = largest_difference(plane, mesh);
  double dw = 0.0;
  for (std::size_t k = 0; k < plane.w.size(); ++k)
    dw = std::max(dw, (plane.w[k] - mesh.w[k]).norm() / std::max(1.0, plane.w[k].norm()));
  std::printf("slide: travelled %.3g m, spin %.3g rad/s, largest difference %.3g m, spin %.3g\n",
              (plane.x.back() - x0).norm(), plane.w.back().norm(), d, dw);
  EXPECT_GT((plane.x.back() - x0).head<2>().norm(), 5e-3);  // crossed several triangles
  EXPECT_LE(d, 1e-9 * kRadius);
  EXPECT_LE(dw, 1e-9);
}

// A frictionless sphere settling in a 90-degree V groove rests on both faces: two contacts with normals
// (0, -+1, 1)/sqrt2, at the height where each face carries m g / sqrt2 with the Hertz overlap.
TEST(MeshWall, SphereInAVGrooveTouchesBothFaces) {
  const double L = 5e-3, X = 10e-3;
  TriangleMesh m;
  const Vec3 a(0, -L, L), b(0, 0, 0), c(0, L, L), a2(X, -L, L), b2(X, 0, 0), c2(X, L, L);
  m.add_triangle(a, b, b2, 0);
  m.add_triangle(a, b2, a2, 1);
  m.add_triangle(b, c, c2, 2);
  m.add_triangle(b, c2, b2, 3);
  DemSettings s = hertz_settings(0.3, 0.0, 0.0);
  ParticleStore p;
  p.add(Vec3(X / 2, 2e-4, 4e-3), kRadius, kDensity);
  SimulationBox box{Vec3(-0.01, -0.01, -0.01), Vec3(0.02, 0.02, 0.02), {false, false, false}};
  DemEngine e(s, box, p);
  e.add_mesh_wall(MeshWall("groove", std::move(m)));
  std::ostringstream plan;
  e.prepare(plan);
  e.advance_to(0.3);
  const Vec3 x = e.particles().position[0];
  std::array<MeshTouch, MeshWall::kMaxContacts> touch;
  const int n = e.mesh_walls()[0].touches(x, kRadius, touch);
  const double mass = e.particles().mass[0];
  const double estar = effective_youngs_modulus(1e6, 0.3);
  const double delta =
      std::pow(mass * 9.81 / std::sqrt(2.0) / (4.0 / 3.0 * estar * std::sqrt(kRadius)), 2.0 / 3.0);
  const double z = (kRadius - delta) * std::sqrt(2.0);
  std::printf("groove: %d contacts, y %.3g m, z %.8g m (two-face Hertz %.8g m), speed %.3g\n", n,
              x.y(), x.z(), z, e.max_speed());
  ASSERT_EQ(n, 2);
  EXPECT_NEAR(std::abs(touch[0].normal.y()), std::sqrt(0.5), 1e-6);
  EXPECT_NEAR(touch[0].normal.y() + touch[1].normal.y(), 0.0, 1e-6);
  EXPECT_NEAR(x.y(), 0.0, 1e-8);
  EXPECT_NEAR(x.z(), z, 1e-3 * delta);
  EXPECT_LT(e.max_speed(), 1e-6);
}

}  // namespace
}  // namespace feedflow

namespace feedflow {
namespace {

// [m] distance from (x, z) to the saw-tooth profile of period 2R and height R (45 deg faces from
// the troughs at x = from + 2kR to the crests at from + (2k+1)R), the strips' cross-section.
double sawtooth_distance(double x, double z, double from, double radius, long teeth) {
  double best = 1e9;
  for (long k = 0; k < teeth; ++k)
    for (int face = 0; face < 2; ++face) {
      const double x0 = from + (2 * k + face) * radius, z0 = face == 0 ? 0.0 : radius;
      const double x1 = x0 + radius, z1 = face == 0 ? radius : 0.0;
      const double dx = x1 - x0, dz = z1 - z0;
      const double s = std::clamp(((x - x0) * dx + (z - z0) * dz) / (dx * dx + dz * dz), 0.0, 1.0);
      best = std::min(best, std::hypot(x - x0 - s * dx, z - z0 - s * dz));
    }
  return best;
}

// The seed's ramp under a 15 mm slab (its strips 45 mm across, 2.1 mm wide) is binned by the
// strips' width, not their length: a query reads a few teeth, not all of them (the grid was 2 x 2
// x 1 cells of 45 mm, each sphere near the ramp testing half of its 96 triangles, a third of a
// stopping layer's step). Binned so, the nearest contact of spheres anywhere over the ramp is
// still the profile's own distance.
TEST(MeshWall, ASawToothRampIsBinnedByItsTeethAndFindsTheNearestFace) {
  const double r = 1.5e-3, from = -6e-3, to = 60e-3, depth = 15e-3;
  const MeshWall ramp("ramp", sawtooth_ramp(from, to, r, depth));
  const std::string grid = ramp.describe();
  const auto at = grid.find(" of ");
  ASSERT_NE(at, std::string::npos) << grid;
  EXPECT_LE(std::stod(grid.substr(at + 4)), 2.0 * r) << grid;  // cells at most a tooth wide
  const long teeth = static_cast<long>(std::ceil((to - from) / (2.0 * r) - 1e-9));
  std::uint32_t state = 12345u;
  const auto uniform = [&state](double lo, double hi) {
    state = state * 1664525u + 1013904223u;
    return lo + (hi - lo) * (static_cast<double>(state >> 8) / 16777216.0);
  };
  int touching = 0;
  for (int n = 0; n < 2000; ++n) {
    const Vec3 x(uniform(0.0, 54e-3), uniform(0.0, depth), uniform(0.2e-3, 3.2e-3));
    std::array<MeshTouch, MeshWall::kMaxContacts> touch;
    const int count = ramp.touches(x, r, touch);
    const double d = sawtooth_distance(x.x(), x.z(), from, r, teeth);
    if (d < r) {
      ASSERT_GT(count, 0) << x.transpose();
      EXPECT_NEAR(touch[0].gap, d, 1e-12) << x.transpose();
      ++touching;
    } else {
      EXPECT_EQ(count, 0) << x.transpose();
    }
  }
  EXPECT_GT(touching, 500);  // the sample reaches the teeth
}

}  // namespace
}  // namespace feedflow
