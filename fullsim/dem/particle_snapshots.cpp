#include "fullsim/dem/particle_snapshots.hpp"

#include <cstdio>
#include <stdexcept>

#include "fullsim/common/hdf5_file.hpp"
#include "fullsim/dem/vec3_arrays.hpp"

namespace feedflow {
namespace {

std::filesystem::path sidecar_of(const std::filesystem::path& hdf5_file) {
  std::filesystem::path p = hdf5_file;
  p.replace_extension(".xdmf");
  return p;
}

}  // namespace

ParticleSnapshots::ParticleSnapshots(std::filesystem::path hdf5_file, long every_steps)
    : hdf5_(std::move(hdf5_file)), every_(every_steps), series_(sidecar_of(hdf5_), hdf5_) {
  if (every_ <= 0) throw std::invalid_argument("snapshot interval must be positive");
}

std::string ParticleSnapshots::group_name(long step) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "/snapshots/step_%09ld", step);
  return buf;
}

std::string ParticleSnapshots::write(const ParticleStore& p, double time, long step,
                                     const SceneOutline* outline) {
  const std::string g = group_name(step);
  const std::size_t n = p.size();
  {
    // The file is made with the first snapshot: a run that ends before it leaves neither file.
    Hdf5File f(hdf5_, count() == 0 ? Hdf5File::Mode::create : Hdf5File::Mode::append);
    if (count() == 0) {
      f.create_group("/snapshots");
      f.set_attribute("/", "format", std::string("feedflow DEM particle snapshots"));
      f.set_attribute("/", "format_version", std::int64_t{1});
      if (outline) write_outline(f, "/outline", *outline);
    }
    f.create_group(g);
    f.set_attribute(g, "time", time);
    f.set_attribute(g, "time_unit", std::string("s"));
    f.set_attribute(g, "step", static_cast<std::int64_t>(step));
    f.write(g + "/position", flatten(p.position), {n, 3}, "m");
    f.write(g + "/velocity", flatten(p.velocity), {n, 3}, "m/s");
    f.write(g + "/angular_velocity", flatten(p.angular_velocity), {n, 3}, "rad/s");
    f.write(g + "/radius", p.radius, {n}, "m");
    f.write(g + "/id", p.id, {n}, "1");
    f.write(g + "/layer", p.layer, {n}, "1");
    f.close();  // on disk before the sidecar names it
  }
  XdmfPointCloud cloud;
  cloud.name = g.substr(g.rfind('/') + 1);
  cloud.time = time;
  cloud.points = n;
  cloud.geometry = g + "/position";
  cloud.attributes = {{"velocity", 3, true, g + "/velocity"},
                      {"angular_velocity", 3, true, g + "/angular_velocity"},
                      {"radius", 1, true, g + "/radius"},
                      {"id", 1, false, g + "/id"},
                      {"layer", 1, true, g + "/layer"}};
  series_.add(std::move(cloud));
  last_step_ = step;
  return g;
}

bool ParticleSnapshots::write_if_due(const ParticleStore& p, double time, long step) {
  if (step % every_ != 0 || step == last_step_) return false;
  write(p, time, step);
  return true;
}

ParticleSnapshot read_particle_snapshot(const std::filesystem::path& hdf5_file,
                                        const std::string& group) {
  const Hdf5File f(hdf5_file, Hdf5File::Mode::read);
  ParticleSnapshot s;
  s.time = f.double_attribute(group, "time");
  s.step = static_cast<long>(f.integer_attribute(group, "step"));
  s.radius = f.read<double>(group + "/radius");
  const std::size_t n = s.radius.size();
  s.position = unflatten(f.read<double>(group + "/position", {n, 3}));
  s.velocity = unflatten(f.read<double>(group + "/velocity", {n, 3}));
  s.angular_velocity = unflatten(f.read<double>(group + "/angular_velocity", {n, 3}));
  s.id = f.read<std::uint32_t>(group + "/id", {n});
  s.layer = f.read<double>(group + "/layer", {n});
  return s;
}

}  // namespace feedflow
