#include "fullsim/dem/dem_checkpoint.hpp"

#include <unistd.h>

#include <cstdio>
#include <limits>
#include <stdexcept>

#include "fullsim/common/hdf5_file.hpp"
#include "fullsim/dem/vec3_arrays.hpp"

namespace feedflow {
namespace {

// A scalar with its unit beside it (attribute "<name>_unit").
void set_quantity(Hdf5File& f, const std::string& object, const std::string& name, double value,
                  const std::string& unit) {
  f.set_attribute(object, name, value);
  f.set_attribute(object, name + "_unit", unit);
}

void write_vec3(Hdf5File& f, const std::string& dataset, const Vec3& v, const std::string& unit) {
  f.write(dataset, std::vector<double>{v.x(), v.y(), v.z()}, {3}, unit);
}

Vec3 read_vec3(const Hdf5File& f, const std::string& dataset) {
  const auto v = f.read<double>(dataset, {3});
  return Vec3(v[0], v[1], v[2]);
}

void write_vec3s(Hdf5File& f, const std::string& dataset, const std::vector<Vec3>& v,
                 const std::string& unit) {
  f.write(dataset, flatten(v), {v.size(), 3}, unit);
}

std::vector<Vec3> read_vec3s(const Hdf5File& f, const std::string& dataset, std::size_t n) {
  return unflatten(f.read<double>(dataset, {n, 3}));
}

std::string wall_group(std::size_t k) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "/walls/%04zu", k);
  return buf;
}

void write_contents(Hdf5File& f, const DemCheckpoint& c) {
  f.set_attribute("/", "format", std::string(kDemCheckpointFormat));
  f.set_attribute("/", "format_version", kDemCheckpointVersion);

  f.create_group("/run");
  f.set_attribute("/run", "step", static_cast<std::int64_t>(c.step));
  set_quantity(f, "/run", "time", c.time, "s");
  set_quantity(f, "/run", "time_step", c.time_step, "s");
  f.set_attribute("/run", "particle_steps", c.particle_steps);
  f.set_attribute("/run", "contact_law", c.contact_law);
  write_vec3(f, "/run/gravity", c.gravity, "m/s^2");

  f.create_group("/box");
  write_vec3(f, "/box/lower", c.box.lower, "m");
  write_vec3(f, "/box/upper", c.box.upper, "m");
  f.write("/box/periodic",
          std::vector<std::uint8_t>{c.box.periodic[0], c.box.periodic[1], c.box.periodic[2]}, {3},
          "");

  const ParticleStore& p = c.particles;
  const std::size_t n = p.size();
  f.create_group("/particles");
  f.set_attribute("/particles", "count", static_cast<std::int64_t>(n));
  f.set_attribute("/particles", "next_id", static_cast<std::int64_t>(p.next_id()));
  f.set_attribute("/particles", "wall_history_stride",
                  static_cast<std::int64_t>(p.wall_history_stride()));
  write_vec3s(f, "/particles/position", p.position, "m");
  write_vec3s(f, "/particles/velocity", p.velocity, "m/s");
  write_vec3s(f, "/particles/angular_velocity", p.angular_velocity, "rad/s");
  write_vec3s(f, "/particles/force", p.force, "N");
  write_vec3s(f, "/particles/torque", p.torque, "N m");
  f.write("/particles/radius", p.radius, {n}, "m");
  f.write("/particles/mass", p.mass, {n}, "kg");
  f.write("/particles/inertia", p.inertia, {n}, "kg m^2");
  f.write("/particles/layer", p.layer, {n}, "1");
  f.write("/particles/id", p.id, {n}, "1");
  f.write("/particles/wall_history", p.wall_history, {n, p.wall_history_stride()}, "SI");

  const NeighbourList& l = c.neighbours;
  const std::size_t entries = l.partner.size();
  f.create_group("/neighbours");
  set_quantity(f, "/neighbours", "skin", l.skin(), "m");
  set_quantity(f, "/neighbours", "cell_size", l.cell_size(), "m");
  f.set_attribute("/neighbours", "history_size", static_cast<std::int64_t>(l.history_size()));
  f.set_attribute("/neighbours", "rebuilds", static_cast<std::int64_t>(l.rebuild_count()));
  f.set_attribute("/neighbours", "carried_over", static_cast<std::int64_t>(l.carried_over()));
  f.write("/neighbours/first", l.first, {l.first.size()}, "1");
  f.write("/neighbours/partner", l.partner, {entries}, "1");
  std::vector<std::uint32_t> ids(2 * entries);
  for (std::size_t e = 0; e < entries; ++e) {
    ids[2 * e] = static_cast<std::uint32_t>(l.entry_keys()[e] >> 32);
    ids[2 * e + 1] = static_cast<std::uint32_t>(l.entry_keys()[e] & 0xffffffffu);
  }
  f.write("/neighbours/pair_ids", ids, {entries, 2}, "1");
  f.write("/neighbours/history", l.history, {entries, l.history_size()}, "SI");
  write_vec3s(f, "/neighbours/reference_position", l.reference_positions(), "m");

  f.create_group("/walls");
  f.set_attribute("/walls", "count", static_cast<std::int64_t>(c.walls.size()));
  for (std::size_t k = 0; k < c.walls.size(); ++k) {
    const Wall& w = c.walls[k];
    const std::string g = wall_group(k);
    f.create_group(g);
    f.set_attribute(g, "name", w.name());
    f.set_attribute(g, "shape", std::string(w.shape() == WallShape::plane ? "plane" : "cylinder"));
    f.set_attribute(g, "particles_inside", static_cast<std::int64_t>(w.particles_inside()));
    set_quantity(f, g, "radius", w.radius(), "m");
    set_quantity(f, g, "removal_time", w.removal_time(), "s");
    f.set_attribute(g, "contact_set", std::string(to_string(w.contact_set())));
    write_vec3(f, g + "/point", w.point(), "m");
    write_vec3(f, g + "/direction", w.direction(), "1");
    write_vec3(f, g + "/velocity", w.velocity(), "m/s");
    write_vec3(f, g + "/angular_velocity", w.angular_velocity(), "rad/s");
  }

  if (c.sink) {
    const OutletSink& s = *c.sink;
    f.create_group("/outlet_sink");
    f.set_attribute("/outlet_sink", "shape", std::string(s.is_box() ? "box" : "plane"));
    set_quantity(f, "/outlet_sink", "removed_mass", s.removed_mass(), "kg");
    write_vec3(f, "/outlet_sink/lower_or_point", s.lower_or_point(), "m");
    write_vec3(f, "/outlet_sink/upper_or_outward", s.upper_or_outward(), s.is_box() ? "m" : "1");
    std::vector<double> t, m, layer;
    std::vector<std::uint32_t> id;
    for (const auto& e : s.events()) {
      t.push_back(e.time);
      id.push_back(e.id);
      m.push_back(e.mass);
      layer.push_back(e.layer);
    }
    f.write("/outlet_sink/event_time", t, {t.size()}, "s");
    f.write("/outlet_sink/event_id", id, {id.size()}, "1");
    f.write("/outlet_sink/event_mass", m, {m.size()}, "kg");
    f.write("/outlet_sink/event_layer", layer, {layer.size()}, "1");
  }

  f.create_group("/guard");
  set_quantity(f, "/guard", "initial_energy", c.guard_initial_energy, "J");
  set_quantity(f, "/guard", "energy_floor", c.guard_energy_floor, "J");
  set_quantity(f, "/guard", "gravity_work", c.guard_gravity_work, "J");
  set_quantity(f, "/guard", "wall_speed", c.guard_wall_speed, "m/s");
}

template <class T>
T checked_count(const Hdf5File& f, const std::string& object, const std::string& name) {
  const std::int64_t v = f.integer_attribute(object, name);
  if (v < 0)
    throw std::runtime_error("DEM checkpoint " + f.path().string() + ": " + object + "@" + name +
                             " is negative");
  return static_cast<T>(v);
}

DemCheckpoint read_contents(const Hdf5File& f) {
  const std::string file = f.path().string();
  auto refuse = [&](const std::string& what) {
    throw std::runtime_error("DEM checkpoint " + file + ": " + what);
  };
  if (f.string_attribute("/", "format") != kDemCheckpointFormat)
    refuse("not a DEM checkpoint (format '" + f.string_attribute("/", "format") + "')");
  const std::int64_t version = f.integer_attribute("/", "format_version");
  if (version != kDemCheckpointVersion)
    refuse("format version " + std::to_string(version) + ", this build reads version " +
           std::to_string(kDemCheckpointVersion));

  DemCheckpoint c;
  c.step = static_cast<long>(f.integer_attribute("/run", "step"));
  c.time = f.double_attribute("/run", "time");
  c.time_step = f.double_attribute("/run", "time_step");
  c.particle_steps = f.double_attribute("/run", "particle_steps");
  c.contact_law = f.string_attribute("/run", "contact_law");
  c.gravity = read_vec3(f, "/run/gravity");

  c.box.lower = read_vec3(f, "/box/lower");
  c.box.upper = read_vec3(f, "/box/upper");
  const auto periodic = f.read<std::uint8_t>("/box/periodic", {3});
  for (int a = 0; a < 3; ++a) c.box.periodic[static_cast<std::size_t>(a)] = periodic[static_cast<std::size_t>(a)] != 0;

  const auto n = checked_count<std::size_t>(f, "/particles", "count");
  const auto stride = checked_count<std::size_t>(f, "/particles", "wall_history_stride");
  ParticleStore& p = c.particles;
  p.position = read_vec3s(f, "/particles/position", n);
  p.velocity = read_vec3s(f, "/particles/velocity", n);
  p.angular_velocity = read_vec3s(f, "/particles/angular_velocity", n);
  p.force = read_vec3s(f, "/particles/force", n);
  p.torque = read_vec3s(f, "/particles/torque", n);
  p.radius = f.read<double>("/particles/radius", {n});
  p.mass = f.read<double>("/particles/mass", {n});
  p.inertia = f.read<double>("/particles/inertia", {n});
  p.layer = f.read<double>("/particles/layer", {n});
  p.id = f.read<std::uint32_t>("/particles/id", {n});
  p.set_wall_history_stride(stride);
  p.wall_history = f.read<double>("/particles/wall_history", {n, stride});
  p.set_next_id(checked_count<std::uint32_t>(f, "/particles", "next_id"));
  for (std::uint32_t id : p.id)
    if (id >= p.next_id()) refuse("particle id " + std::to_string(id) + " is not below next_id");

  const auto h = checked_count<std::size_t>(f, "/neighbours", "history_size");
  auto first = f.read<std::uint32_t>("/neighbours/first", {n + 1});
  const std::size_t entries = f.dims("/neighbours/partner").at(0);
  auto partner = f.read<std::uint32_t>("/neighbours/partner", {entries});
  const auto ids = f.read<std::uint32_t>("/neighbours/pair_ids", {entries, 2});
  auto history = f.read<double>("/neighbours/history", {entries, h});
  // The entries must name the particles in their slots (a damaged list is refused here, not
  // found as a wrong force later).
  std::vector<std::uint64_t> keys(entries);
  if (first.front() != 0 || first.back() != entries) refuse("neighbour rows do not span the entries");
  for (std::size_t i = 0; i < n; ++i) {
    if (first[i] > first[i + 1]) refuse("neighbour rows are not ordered");
    for (std::size_t e = first[i]; e < first[i + 1]; ++e) {
      if (partner[e] >= n) refuse("neighbour entry " + std::to_string(e) + " names no particle");
      if (ids[2 * e] != p.id[i] || ids[2 * e + 1] != p.id[partner[e]])
        refuse("neighbour entry " + std::to_string(e) + " has id pair (" +
               std::to_string(ids[2 * e]) + ", " + std::to_string(ids[2 * e + 1]) +
               ") but its slots hold ids (" + std::to_string(p.id[i]) + ", " +
               std::to_string(p.id[partner[e]]) + ")");
      keys[e] = static_cast<std::uint64_t>(ids[2 * e]) << 32 | ids[2 * e + 1];
    }
  }
  const std::size_t references = f.dims("/neighbours/reference_position").at(0);
  c.neighbours = NeighbourList::restored(
      f.double_attribute("/neighbours", "skin"), h, f.double_attribute("/neighbours", "cell_size"),
      checked_count<std::size_t>(f, "/neighbours", "rebuilds"),
      checked_count<std::size_t>(f, "/neighbours", "carried_over"), std::move(first),
      std::move(partner), std::move(history), std::move(keys),
      read_vec3s(f, "/neighbours/reference_position", references));

  const auto walls = checked_count<std::size_t>(f, "/walls", "count");
  for (std::size_t k = 0; k < walls; ++k) {
    const std::string g = wall_group(k);
    const std::string name = f.string_attribute(g, "name");
    const std::string shape = f.string_attribute(g, "shape");
    const Vec3 point = read_vec3(f, g + "/point");
    const Vec3 direction = read_vec3(f, g + "/direction");
    Wall w = shape == "plane" ? Wall::plane(name, point, direction)
             : shape == "cylinder"
                 ? Wall::cylinder(name, point, direction, f.double_attribute(g, "radius"),
                                  f.integer_attribute(g, "particles_inside") != 0)
                 : (refuse("wall " + g + " has an unknown shape '" + shape + "'"), Wall());
    const std::string set = f.string_attribute(g, "contact_set");
    if (set != to_string(WallContactSet::particle_wall) &&
        set != to_string(WallContactSet::frictionless))
      refuse("wall " + g + " has an unknown contact set '" + set + "'");
    w.with_contact_set(set == to_string(WallContactSet::frictionless)
                           ? WallContactSet::frictionless
                           : WallContactSet::particle_wall);
    w.moving(read_vec3(f, g + "/velocity"), read_vec3(f, g + "/angular_velocity"))
        .removed_at(f.double_attribute(g, "removal_time"))
        .placed(point, direction);
    c.walls.push_back(std::move(w));
  }

  if (f.exists("/outlet_sink")) {
    const std::string shape = f.string_attribute("/outlet_sink", "shape");
    if (shape != "box" && shape != "plane") refuse("outlet sink has an unknown shape '" + shape + "'");
    const auto t = f.read<double>("/outlet_sink/event_time");
    const auto id = f.read<std::uint32_t>("/outlet_sink/event_id", {t.size()});
    const auto m = f.read<double>("/outlet_sink/event_mass", {t.size()});
    // (a checkpoint written before the layers were booked: NaN, unknown)
    const auto layer = f.exists("/outlet_sink/event_layer")
                           ? f.read<double>("/outlet_sink/event_layer", {t.size()})
                           : std::vector<double>(t.size(), std::numeric_limits<double>::quiet_NaN());
    std::vector<SinkEvent> events(t.size());
    for (std::size_t k = 0; k < t.size(); ++k) events[k] = {t[k], id[k], m[k], layer[k]};
    c.sink = OutletSink::restored(shape == "box", read_vec3(f, "/outlet_sink/lower_or_point"),
                                  read_vec3(f, "/outlet_sink/upper_or_outward"),
                                  f.double_attribute("/outlet_sink", "removed_mass"),
                                  std::move(events));
  }

  c.guard_initial_energy = f.double_attribute("/guard", "initial_energy");
  c.guard_energy_floor = f.double_attribute("/guard", "energy_floor");
  c.guard_gravity_work = f.double_attribute("/guard", "gravity_work");
  c.guard_wall_speed = f.double_attribute("/guard", "wall_speed");
  return c;
}

}  // namespace

void write_dem_checkpoint(const std::filesystem::path& path, const DemCheckpoint& checkpoint) {
  namespace fs = std::filesystem;
  const fs::path temporary = path.string() + ".tmp" + std::to_string(::getpid());
  try {
    Hdf5File f(temporary, Hdf5File::Mode::create);
    write_contents(f, checkpoint);
    f.close();
  } catch (const std::exception& e) {
    std::error_code ec;
    fs::remove(temporary, ec);
    throw std::runtime_error("cannot write DEM checkpoint " + path.string() + ": " + e.what());
  }
  std::error_code ec;
  fs::rename(temporary, path, ec);
  if (ec) {
    fs::remove(temporary, ec);
    throw std::runtime_error("cannot write DEM checkpoint " + path.string() + ": " + ec.message());
  }
}

DemCheckpoint read_dem_checkpoint(const std::filesystem::path& path) {
  std::optional<Hdf5File> f;
  try {
    f.emplace(path, Hdf5File::Mode::read);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error("DEM checkpoint " + path.string() + " refused: " + e.what());
  }
  return read_dem_checkpoint(*f);
}

void write_dem_checkpoint(Hdf5File& file, const DemCheckpoint& checkpoint) {
  write_contents(file, checkpoint);
}

DemCheckpoint read_dem_checkpoint(const Hdf5File& file) {
  try {
    return read_contents(file);
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    if (what.rfind("DEM checkpoint", 0) == 0) throw;
    throw std::runtime_error("DEM checkpoint " + file.path().string() + " refused: " + what);
  }
}

}  // namespace feedflow
