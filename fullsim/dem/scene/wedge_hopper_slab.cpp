#include "fullsim/dem/scene/wedge_hopper_slab.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "fullsim/dem/scene/hopper_rain.hpp"
#include "models/core/errors.hpp"
#include "models/units/angle.hpp"

namespace feedflow {
double WedgeHopperSlab::apex_depth() const { return 0.5 * outlet_width / std::tan(semi_angle); }
double WedgeHopperSlab::bin_bottom() const {
  return 0.5 * (bin_width - outlet_width) / std::tan(semi_angle);
}
double WedgeHopperSlab::fill_top() const { return fill_height - apex_depth(); }
double WedgeHopperSlab::half_width(double z) const {
  return z < bin_bottom() ? 0.5 * outlet_width + z * std::tan(semi_angle) : 0.5 * bin_width;
}
bool WedgeHopperSlab::periodic() const {
  return faces == SlabFaces::periodic ||
         (faces == SlabFaces::automatic && depth >= 4.0 * radius * (1.0 + skin_fraction));
}
bool WedgeHopperSlab::one_layer() const { return depth < 2.0 * radius * (1.0 + 1e-3); }
SlabFaces WedgeHopperSlab::built_faces() const {
  if (periodic()) return SlabFaces::periodic;
  if (faces == SlabFaces::planar) return SlabFaces::planar;
  return faces == SlabFaces::frictionless ? SlabFaces::frictionless : SlabFaces::frictional;
}
double WedgeHopperSlab::wall_top() const { return fill_top() + 0.1; }

void WedgeHopperSlab::check() const {
  auto bad = [](const char* key, const std::string& what) { throw InputError("", key, what); };
  if (!(semi_angle > 0.0 && semi_angle < 0.5 * std::numbers::pi))
    bad("hopper.semi_angle", "the DEM wedge needs a semi-angle between 0 and 90 deg");
  if (!(outlet_width > 2.0 * radius))
    bad("hopper.outlet_width", "the outlet must be wider than one particle");
  if (!(bin_width > outlet_width)) bad("hopper.bin_width", "the DEM wedge needs a bin wider than the outlet");
  if (!(fill_top() > 4.0 * radius)) bad("hopper.fill_height", "the fill ends below the outlet plane");
  if (!(depth >= 2.0 * radius)) bad("dem.slab_depth", "the slab must hold one particle layer (>= 2 R)");
  const double cutoff = 2.0 * radius * (1.0 + skin_fraction);
  if (faces == SlabFaces::periodic && depth < 2.0 * cutoff) {
    char what[200];
    std::snprintf(
        what, sizeof what,
        "periodic faces need a slab at least two neighbour cutoffs deep (%.4g mm); "
        "this one is %.4g mm ([dem] slab_depth; or choose \"frictional\" or \"frictionless\")",
        2e3 * cutoff, 1e3 * depth);
    bad("dem.slab_faces", what);
  }
  if (faces == SlabFaces::planar && !one_layer()) {
    char what[200];
    std::snprintf(what, sizeof what,
                  "planar holds one layer in its mid-plane: the slab must be less than 2 R x 1.001 "
                  "(%.4g mm) deep; this one is %.4g mm ([dem] slab_depth; or choose \"frictional\" "
                  "or \"frictionless\")",
                  2e3 * radius * (1.0 + 1e-3), 1e3 * depth);
    bad("dem.slab_faces", what);
  }
}

SimulationBox WedgeHopperSlab::box() const {
  SimulationBox b;
  const double margin = 4.0 * radius;
  b.lower = Vec3(-0.5 * bin_width - margin, 0.0, sink_height() - margin);
  b.upper = Vec3(0.5 * bin_width + margin, depth, wall_top() + 0.05);
  b.periodic = {false, periodic(), false};
  return b;
}

MeshWall WedgeHopperSlab::wedge_mesh() const {
  const double a = 0.5 * outlet_width, b = 0.5 * bin_width, zb = bin_bottom();
  const double y0 = -4.0 * radius, y1 = depth + 4.0 * radius;
  TriangleMesh mesh;
  mesh.source = "wedge walls built in code";
  // Strips about as tall as the slab is deep: the mesh grid takes its cells from the triangle
  // size, so small triangles let a sphere away from the walls skip them (two triangles spanning
  // the wedge made every sphere below the bin test both walls every step, a quarter of the
  // fill's time). Shared edges are welded and counted once.
  const int strips = std::max(1, static_cast<int>(std::ceil(zb / (y1 - y0))));
  for (double side : {-1.0, 1.0})
    for (int k = 0; k < strips; ++k) {
      const double z0 = zb * k / strips, z1 = zb * (k + 1) / strips;
      const double x0 = side * (a + (b - a) * z0 / zb), x1 = side * (a + (b - a) * z1 / zb);
      const Vec3 p0(x0, y0, z0), p1(x1, y0, z1), p2(x1, y1, z1), p3(x0, y1, z0);
      mesh.add_triangle(p0, p1, p2, mesh.triangles.size());
      mesh.add_triangle(p0, p2, p3, mesh.triangles.size());
    }
  return MeshWall("wedge", std::move(mesh));
}

SceneOutline WedgeHopperSlab::outline() const {
  const double a = 0.5 * outlet_width, b = 0.5 * bin_width, zb = bin_bottom(), y = 0.5 * depth;
  SceneOutline o;
  for (double side : {-1.0, 1.0}) {
    o.push_back({Vec3(side * a, y, 0.0), Vec3(side * b, y, zb)});
    o.push_back({Vec3(side * b, y, zb), Vec3(side * b, y, wall_top())});
  }
  return o;
}

void WedgeHopperSlab::add_walls(DemEngine& engine) const {
  const double b = 0.5 * bin_width;
  engine.set_outline(outline());
  engine.add_mesh_wall(wedge_mesh());
  engine.add_wall(Wall::plane("bin left", Vec3(-b, 0, 0), Vec3::UnitX()));
  engine.add_wall(Wall::plane("bin right", Vec3(b, 0, 0), -Vec3::UnitX()));
  if (built_faces() == SlabFaces::planar) {
    engine.hold_in_plane(1);  // no faces: nothing moves across the slab
  } else if (!periodic()) {
    const WallContactSet set = built_faces() == SlabFaces::frictionless
                                   ? WallContactSet::frictionless
                                   : WallContactSet::particle_wall;
    engine.add_wall(Wall::plane("front", Vec3(0, 0, 0), Vec3::UnitY()).with_contact_set(set));
    engine.add_wall(Wall::plane("back", Vec3(0, depth, 0), -Vec3::UnitY()).with_contact_set(set));
  }
  engine.add_wall(Wall::plane("gate", Vec3(0, 0, 0), Vec3::UnitZ()));
  engine.set_outlet_sink(OutletSink::plane(Vec3(0, 0, sink_height()), -Vec3::UnitZ()));
}

std::function<bool(const Vec3&, double)> WedgeHopperSlab::admits() const {
  const WedgeHopperSlab h = *this;
  return [h](const Vec3& x, double r) {
    if (x.z() < r || x.z() > h.wall_top()) return false;
    const double wedge = 0.5 * h.outlet_width + x.z() * std::tan(h.semi_angle) - r / std::cos(h.semi_angle);
    return std::abs(x.x()) <= std::min(wedge, 0.5 * h.bin_width - r);
  };
}

double WedgeHopperSlab::fill_mass(double density, double phi) const {
  const double zt = fill_top(), zb = std::min(zt, bin_bottom());
  const double area = zb * (outlet_width + 2.0 * half_width(zb)) * 0.5 +
                      std::max(0.0, zt - bin_bottom()) * bin_width;
  return area * depth * density * phi;
}

RainFillSettings WedgeHopperSlab::rain(double density, int bands, std::uint64_t seed) const {
  const double b = 0.5 * bin_width - radius;
  const double region = std::max(8.0 * radius, 0.02);
  Vec3 lower(-b, 0.0, 2.0 * radius), upper(b, depth, 2.0 * radius + region);
  if (!periodic()) {
    lower.y() = radius;
    upper.y() = depth - radius;
    if (one_layer()) lower.y() = upper.y() = 0.5 * depth;
  }
  // A one-layer slab packs discs (area fraction ~0.82, volume share 2/3 of it); deeper ~0.6.
  const double phi = periodic() ? 0.6 : 0.82 * (4.0 / 3.0 * radius) / depth;
  return hopper_rain_settings(
      {lower, upper, radius, density, fill_mass(density, phi), fill_top(), wall_top(), bands, seed, admits()});
}

std::string WedgeHopperSlab::describe_faces() const {
  const SlabFaces built = built_faces();
  std::string s = built == SlabFaces::periodic ? "periodic front/back"
                  : built == SlabFaces::planar
                      ? "none: one layer held in its mid-plane (no motion across the slab, spin "
                        "about its normal only), a disc packing without face friction"
                  : built == SlabFaces::frictionless
                      ? "frictionless front and back planes (P-W normal law and damping, no "
                        "sliding or rolling resistance)"
                      : "front and back planes with the particle-wall friction";
  if (faces == SlabFaces::automatic)
    s += " (slab_faces by default: periodic from two cutoffs deep)";
  if (built != SlabFaces::planar && built != SlabFaces::periodic && one_layer())
    s += "; one layer that leaves its mid-plane once it flows (a compressed layer buckles) and "
         "presses on the faces";
  if (built == SlabFaces::frictional) s += "; errs towards arching and a lower rate";
  return s;
}

std::string WedgeHopperSlab::describe() const {
  char buf[600];
  std::snprintf(buf, sizeof buf,
                "  hopper slab: wedge theta = %.4g deg, outlet W = %.4g mm, bin B = %.4g mm, fill "
                "H = %.4g m above the apex (%.4g m above the outlet), wedge-bin transition at "
                "%.4g m, slab depth %.4g mm\n",
                in_degrees(semi_angle), outlet_width * 1e3, bin_width * 1e3, fill_height,
                fill_top(), bin_bottom(), depth * 1e3);
  return buf + ("  slab faces: " + describe_faces() + "\n");
}

}  // namespace feedflow
