#include "fullsim/dem/scene/conical_hopper.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "fullsim/dem/scene/hopper_rain.hpp"
#include "models/core/errors.hpp"
#include "models/core/printf_format.hpp"
#include "models/units/angle.hpp"

namespace feedflow {
namespace {

constexpr double kPi = std::numbers::pi;

// The inward normals of the sector's sides (through the axis at azimuths -alpha/2, +alpha/2).
Vec3 side_a_normal(double alpha) { return Vec3(std::sin(0.5 * alpha), std::cos(0.5 * alpha), 0.0); }
Vec3 side_b_normal(double alpha) { return Vec3(std::sin(0.5 * alpha), -std::cos(0.5 * alpha), 0.0); }

}  // namespace

bool ConicalHopper::whole() const { return sector >= 2.0 * kPi * (1.0 - 1e-9); }
double ConicalHopper::share() const { return whole() ? 1.0 : sector / (2.0 * kPi); }
double ConicalHopper::apex_depth() const { return 0.5 * outlet_diameter / std::tan(semi_angle); }
double ConicalHopper::bin_bottom() const {
  return 0.5 * (bin_diameter - outlet_diameter) / std::tan(semi_angle);
}
double ConicalHopper::fill_top() const { return fill_height - apex_depth(); }
double ConicalHopper::wall_top() const { return fill_top() + 0.1; }
double ConicalHopper::radius_at(double z) const {
  return z < bin_bottom() ? 0.5 * outlet_diameter + z * std::tan(semi_angle) : 0.5 * bin_diameter;
}

void ConicalHopper::check() const {
  auto bad = [](const char* key, const std::string& what) { throw InputError("", key, what); };
  if (!(semi_angle > 0.0 && semi_angle < 0.5 * kPi))
    bad("hopper.semi_angle", "the DEM cone needs a semi-angle between 0 and 90 deg");
  if (!(outlet_diameter > 2.0 * radius))
    bad("hopper.outlet_width", "the outlet must be wider than one particle");
  if (!(bin_diameter > outlet_diameter)) bad("hopper.bin_width", "the DEM cone needs a bin wider than the outlet");
  if (!(fill_top() > 4.0 * radius)) bad("hopper.fill_height", "the fill ends below the outlet plane");
  if (!(whole() || (sector > 0.0 && sector <= 0.5 * kPi * (1.0 + 1e-9))))
    bad("dem.sector_angle", format("a sector is at most 90 deg, or the whole 360 deg; this one is %.4g deg",
                                   in_degrees(sector)));
  // The narrow end of the sector at the outlet rim must hold a grain between its sides.
  if (!whole() && 0.5 * outlet_diameter * std::sin(0.5 * sector) < 2.0 * radius)
    bad("dem.sector_angle", format("a %.4g deg sector is narrower than two particle radii at the outlet rim "
                                   "(%.4g mm wide there); take a wider sector or the whole cone",
                                   in_degrees(sector), 1e3 * outlet_diameter * std::sin(0.5 * sector)));
}

SimulationBox ConicalHopper::box() const {
  const double b = 0.5 * bin_diameter, m = 4.0 * radius;
  SimulationBox box;
  const double half_y = whole() ? b : b * std::sin(0.5 * sector);
  box.lower = Vec3(whole() ? -b - m : -m, -half_y - m, sink_height() - m);
  box.upper = Vec3(b + m, half_y + m, wall_top() + 0.05);
  box.periodic = {false, false, false};
  return box;
}

MeshWall ConicalHopper::cone_mesh() const {
  const double a = 0.5 * outlet_diameter, b = 0.5 * bin_diameter, zb = bin_bottom();
  // Facets whose middle stands at most R/20 inside the true cone at its widest.
  const double step = std::acos(1.0 - radius / (20.0 * b));
  const int around = std::max(24, static_cast<int>(std::ceil(2.0 * kPi / step)));
  // Rings about as far apart as the facets are wide at the top (the mesh grid takes its cells
  // from the triangle size).
  const double chord = 2.0 * kPi * b / around;
  const int rings = std::max(1, static_cast<int>(std::ceil(zb / std::cos(semi_angle) / chord)));
  TriangleMesh mesh;
  mesh.source = "cone wall built in code";
  auto at = [&](int ring, int k) {
    const double z = zb * ring / rings, r = a + (b - a) * ring / rings;
    const double phi = 2.0 * kPi * k / around;
    return Vec3(r * std::cos(phi), r * std::sin(phi), z);
  };
  for (int ring = 0; ring < rings; ++ring)
    for (int k = 0; k < around; ++k) {
      const Vec3 p0 = at(ring, k), p1 = at(ring, k + 1), p2 = at(ring + 1, k + 1), p3 = at(ring + 1, k);
      mesh.add_triangle(p0, p1, p2, mesh.triangles.size());
      mesh.add_triangle(p0, p2, p3, mesh.triangles.size());
    }
  return MeshWall("cone", std::move(mesh));
}

SceneOutline ConicalHopper::outline() const {
  const double a = 0.5 * outlet_diameter, b = 0.5 * bin_diameter, zb = bin_bottom();
  SceneOutline o;
  for (double side : whole() ? std::vector<double>{-1.0, 1.0} : std::vector<double>{1.0}) {
    o.push_back({Vec3(side * a, 0.0, 0.0), Vec3(side * b, 0.0, zb)});
    o.push_back({Vec3(side * b, 0.0, zb), Vec3(side * b, 0.0, wall_top())});
  }
  return o;
}

void ConicalHopper::add_walls(DemEngine& engine) const {
  engine.set_outline(outline());
  engine.add_mesh_wall(cone_mesh());
  engine.add_wall(Wall::cylinder("bin", Vec3::Zero(), Vec3::UnitZ(), 0.5 * bin_diameter, true));
  if (!whole()) {
    engine.add_wall(Wall::plane("side a", Vec3::Zero(), side_a_normal(sector)).with_contact_set(WallContactSet::frictionless));
    engine.add_wall(Wall::plane("side b", Vec3::Zero(), side_b_normal(sector)).with_contact_set(WallContactSet::frictionless));
  }
  engine.add_wall(Wall::plane("gate", Vec3::Zero(), Vec3::UnitZ()));
  engine.set_outlet_sink(OutletSink::plane(Vec3(0, 0, sink_height()), -Vec3::UnitZ()));
}

std::function<bool(const Vec3&, double)> ConicalHopper::admits() const {
  const ConicalHopper h = *this;
  return [h](const Vec3& x, double r) {
    if (x.z() < r || x.z() > h.wall_top()) return false;
    const double rho = std::hypot(x.x(), x.y());
    const double cone = 0.5 * h.outlet_diameter + x.z() * std::tan(h.semi_angle) - r / std::cos(h.semi_angle);
    if (rho > std::min(cone, 0.5 * h.bin_diameter - r)) return false;
    return h.whole() || (x.dot(side_a_normal(h.sector)) >= r && x.dot(side_b_normal(h.sector)) >= r);
  };
}

double ConicalHopper::fill_mass(double density, double phi) const {
  const double zt = fill_top(), zc = std::min(zt, bin_bottom());
  const double a = 0.5 * outlet_diameter, c = radius_at(zc), b = 0.5 * bin_diameter;
  const double volume = kPi / 3.0 * zc * (a * a + a * c + c * c) + kPi * b * b * std::max(0.0, zt - bin_bottom());
  return share() * volume * density * phi;
}

RainFillSettings ConicalHopper::rain(double density, int bands, std::uint64_t seed) const {
  const SimulationBox b = box();
  const double region = std::max(8.0 * radius, 0.02);
  RainFillSettings s = hopper_rain_settings({Vec3(b.lower.x(), b.lower.y(), 2.0 * radius),
                                             Vec3(b.upper.x(), b.upper.y(), 2.0 * radius + region),
                                             radius, density, fill_mass(density, kPouredPacking),
                                             fill_top(), wall_top(), bands, seed, admits()});
  // At the start the region lies where the cone is narrowest: a random point of the region's
  // box lands in the cone that rarely, so the tries per sphere grow by the box's area over the
  // cone's section there (a 20 deg cone's quarter: x 42).
  const double open = share() * kPi * std::pow(radius_at(s.region_upper.z()) - radius, 2);
  const double area = (b.upper.x() - b.lower.x()) * (b.upper.y() - b.lower.y());
  s.attempts = static_cast<int>(std::min(1e5, std::ceil(s.attempts * std::max(1.0, area / open))));
  return s;
}

std::string ConicalHopper::simulated_part() const {
  if (whole()) return "the whole cone in 3D";
  return format("a %.4g deg sector of the cone in 3D between frictionless symmetry planes (masses x %.4g)",
                in_degrees(sector), 1.0 / share());
}

std::string ConicalHopper::describe() const {
  return format("  conical hopper: theta = %.4g deg, outlet D = %.4g mm, bin B = %.4g mm, fill H = %.4g m "
                "above the apex (%.4g m above the outlet), cone-bin transition at %.4g m\n"
                "  simulated: %s\n",
                in_degrees(semi_angle), outlet_diameter * 1e3, bin_diameter * 1e3, fill_height, fill_top(),
                bin_bottom(), simulated_part().c_str());
}

}  // namespace feedflow
