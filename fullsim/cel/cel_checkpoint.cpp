#include "fullsim/cel/cel_checkpoint.hpp"

#include <stdexcept>

#include "fullsim/common/hdf5_file.hpp"

namespace feedflow::cel {
namespace {

template <class V>
std::vector<double> flatten(const std::vector<V>& v) {
  std::vector<double> out;
  out.reserve(v.size() * V::SizeAtCompileTime);
  for (const auto& x : v)
    for (int k = 0; k < V::SizeAtCompileTime; ++k) out.push_back(x.data()[k]);
  return out;
}

template <class V>
std::vector<V> unflatten(const std::vector<double>& d) {
  std::vector<V> out(d.size() / V::SizeAtCompileTime);
  for (std::size_t i = 0; i < out.size(); ++i)
    for (int k = 0; k < V::SizeAtCompileTime; ++k) out[i].data()[k] = d[i * V::SizeAtCompileTime + k];
  return out;
}

}  // namespace

void write_cel_checkpoint(Hdf5File& f, const CelSceneRun& run) {
  const CelSolverState s = run.solver().state();
  {
    f.set_attribute("/", "format", std::string(kCelCheckpointFormat));
    f.set_attribute("/", "format_version", static_cast<std::int64_t>(kCelCheckpointVersion));
    const auto& g = run.solver().grid();
    f.set_attribute("/", "nx", static_cast<std::int64_t>(g.nx));
    f.set_attribute("/", "ny", static_cast<std::int64_t>(g.ny));
    f.set_attribute("/", "cell_size", g.cell_size);
    f.set_attribute("/", "symmetry", std::string(symmetry_name(g.symmetry)));
    const std::size_t n = g.cell_count(), m = g.node_count();
    f.create_group("/cells");
    f.write("/cells/volume_fraction", s.cells.volume_fraction, {n}, "1");
    f.write("/cells/mass", s.cells.mass, {n}, "kg/m");
    f.write("/cells/stress", flatten(s.cells.stress), {n, 9}, "Pa");
    f.write("/cells/void_ratio", s.cells.void_ratio, {n}, "1");
    f.write("/cells/solid", s.cells.solid, {n}, "1");
    f.write("/cells/wave_speed", s.cells.wave_speed, {n}, "m/s");
    f.write("/cells/volume_rate", s.cells.volume_rate, {n}, "1/s");
    f.create_group("/nodes");
    f.write("/nodes/velocity", flatten(s.nodes.velocity), {m, 2}, "m/s");
    f.write("/nodes/mass", s.nodes.mass, {m}, "kg/m");
    f.write("/nodes/force", flatten(s.nodes.force), {m, 2}, "N/m");
    f.write("/nodes/constraint", s.nodes.constraint, {m}, "1");
    f.create_group("/walls");
    const std::size_t w = s.wall_removal_times.size();
    if (w > 0) {
      f.write("/walls/removal_time", s.wall_removal_times, {w}, "s");
      f.write("/walls/motion_start", s.wall_motion_starts, {w}, "s");
      f.write("/walls/motion_end", s.wall_motion_ends, {w}, "s");
    }
    f.set_attribute("/walls", "count", static_cast<std::int64_t>(w));
    f.create_group("/discharge");
    std::vector<double> times, masses;
    for (const auto& d : s.discharge.history()) times.push_back(d.time), masses.push_back(d.mass);
    f.write("/discharge/time", times, {times.size()}, "s");
    f.write("/discharge/mass", masses, {masses.size()}, "kg/m");
    f.set_attribute("/discharge", "total", s.discharge.total());
    f.set_attribute("/discharge", "momentum_x", s.discharge.momentum().x());
    f.set_attribute("/discharge", "momentum_y", s.discharge.momentum().y());
    f.create_group("/solver");
    f.set_attribute("/solver", "void_node_mass", s.void_node_mass);
    f.set_attribute("/solver", "time", s.time);
    f.set_attribute("/solver", "dt_previous", s.dt_previous);
    f.set_attribute("/solver", "steps", static_cast<std::int64_t>(s.steps));
    f.set_attribute("/solver", "cell_updates", static_cast<std::int64_t>(s.cell_updates));
    f.set_attribute("/solver", "removed_mass", s.removed_mass);
    f.set_attribute("/solver", "settling_damping", s.settling_damping);
    f.set_attribute("/solver", "frame_start", s.frame_start);
    const SceneRunState& r = run.run_state();
    f.create_group("/run");
    f.set_attribute("/run", "phase", static_cast<std::int64_t>(r.phase == ScenePhase::event));
    f.set_attribute("/run", "event_time", r.event_time);
    f.set_attribute("/run", "peak_kinetic_energy", r.peak_kinetic_energy);
  }
}

void write_cel_checkpoint(const std::filesystem::path& file, const CelSceneRun& run,
                          const std::vector<std::vector<double>>& samples) {
  const auto temporary = std::filesystem::path(file.string() + ".part");
  {
    Hdf5File f(temporary, Hdf5File::Mode::create);
    write_cel_checkpoint(f, run);
    f.create_group("/scene");
    std::vector<double> table;
    const std::size_t cols = samples.empty() ? 0 : samples.front().size();
    for (const auto& row : samples) table.insert(table.end(), row.begin(), row.end());
    if (!samples.empty()) f.write("/scene/series", table, {samples.size(), cols}, "SI");
    f.close();
  }
  std::filesystem::rename(temporary, file);
}

CelCheckpoint read_cel_checkpoint(const std::filesystem::path& file, const CelGrid& g) {
  const Hdf5File f(file, Hdf5File::Mode::read);
  CelCheckpoint c = read_cel_checkpoint(f, g);
  if (f.exists("/scene/series")) {
    const auto dims = f.dims("/scene/series");
    const auto table = f.read<double>("/scene/series");
    for (std::size_t k = 0; dims.size() == 2 && dims[1] > 0 && k + dims[1] <= table.size(); k += dims[1])
      c.samples.emplace_back(table.begin() + k, table.begin() + k + dims[1]);
  }
  return c;
}

CelCheckpoint read_cel_checkpoint(const Hdf5File& f, const CelGrid& g) {
  const std::filesystem::path& file = f.path();
  const auto refuse = [&](const std::string& why) {
    throw std::runtime_error("checkpoint " + file.string() + ": " + why);
  };
  if (!f.exists("/cells") || f.string_attribute("/", "format") != kCelCheckpointFormat)
    refuse("not a CEL checkpoint");
  if (f.integer_attribute("/", "format_version") != kCelCheckpointVersion)
    refuse("format version " + std::to_string(f.integer_attribute("/", "format_version")) +
           ", this build reads version " + std::to_string(kCelCheckpointVersion));
  if (f.integer_attribute("/", "nx") != g.nx || f.integer_attribute("/", "ny") != g.ny ||
      f.double_attribute("/", "cell_size") != g.cell_size)
    refuse("written for another grid (another case or cell size)");
  // Checkpoints written before axisymmetric grids existed are plane strain.
  std::string symmetry = symmetry_name(GridSymmetry::plane_strain);
  try {
    symmetry = f.string_attribute("/", "symmetry");
  } catch (const std::runtime_error&) {
  }
  if (symmetry != symmetry_name(g.symmetry))
    refuse("written for a " + symmetry + " grid, this run's is " + symmetry_name(g.symmetry));
  const std::size_t n = g.cell_count(), m = g.node_count();
  CelCheckpoint c;
  CelSolverState& s = c.solver;
  s.cells.volume_fraction = f.read<double>("/cells/volume_fraction", {n});
  s.cells.mass = f.read<double>("/cells/mass", {n});
  s.cells.stress = unflatten<Eigen::Matrix3d>(f.read<double>("/cells/stress", {n, 9}));
  s.cells.void_ratio = f.read<double>("/cells/void_ratio", {n});
  s.cells.solid = f.read<std::uint8_t>("/cells/solid", {n});
  s.cells.wave_speed = f.read<double>("/cells/wave_speed", {n});
  s.cells.volume_rate = f.read<double>("/cells/volume_rate", {n});
  s.nodes.velocity = unflatten<NodeVector>(f.read<double>("/nodes/velocity", {m, 2}));
  s.nodes.mass = f.read<double>("/nodes/mass", {m});
  s.nodes.force = unflatten<NodeVector>(f.read<double>("/nodes/force", {m, 2}));
  s.nodes.constraint = f.read<std::uint8_t>("/nodes/constraint", {m});
  if (f.integer_attribute("/walls", "count") > 0) {
    s.wall_removal_times = f.read<double>("/walls/removal_time");
    s.wall_motion_starts = f.read<double>("/walls/motion_start");
    s.wall_motion_ends = f.read<double>("/walls/motion_end");
  }
  const auto times = f.read<double>("/discharge/time");
  const auto masses = f.read<double>("/discharge/mass");
  std::vector<DischargeSample> history;
  for (std::size_t k = 0; k < times.size() && k < masses.size(); ++k) history.push_back({times[k], masses[k]});
  s.discharge = DischargeLedger(f.double_attribute("/discharge", "total"),
                                NodeVector(f.double_attribute("/discharge", "momentum_x"),
                                           f.double_attribute("/discharge", "momentum_y")),
                                std::move(history));
  s.void_node_mass = f.double_attribute("/solver", "void_node_mass");
  s.time = f.double_attribute("/solver", "time");
  s.dt_previous = f.double_attribute("/solver", "dt_previous");
  s.steps = f.integer_attribute("/solver", "steps");
  s.cell_updates = f.integer_attribute("/solver", "cell_updates");
  s.removed_mass = f.double_attribute("/solver", "removed_mass");
  s.settling_damping = f.double_attribute("/solver", "settling_damping");
  s.frame_start = f.double_attribute("/solver", "frame_start");
  c.run.phase = f.integer_attribute("/run", "phase") ? ScenePhase::event : ScenePhase::gravity;
  c.run.event_time = f.double_attribute("/run", "event_time");
  c.run.peak_kinetic_energy = f.double_attribute("/run", "peak_kinetic_energy");
  return c;
}

}  // namespace feedflow::cel
