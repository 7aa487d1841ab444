#include "designer/simulate/dem_scene_run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>
#include <unistd.h>

#include "designer/design/verdict_builder.hpp"
#include "fullsim/common/interrupt_request.hpp"
#include "fullsim/common/progress_line.hpp"
#include "fullsim/dem/particle_snapshots.hpp"

namespace feedflow {
namespace {

constexpr long kMaxChunk = 200;  // steps between interrupt checks and progress updates

// The engine's checkpoint plus the scene group, written whole (temporary, then renamed).
void write_scene_checkpoint(const DemEngine& engine, const std::filesystem::path& path,
                            const TimeSeries& series, const DemSceneRun& run) {
  const std::filesystem::path temporary = path.string() + ".scene" + std::to_string(::getpid());
  engine.write_checkpoint(temporary);
  {
    Hdf5File f(temporary, Hdf5File::Mode::append);
    f.create_group("/scene");
    std::vector<double> rows;
    for (const auto& r : series.rows()) rows.insert(rows.end(), r.begin(), r.end());
    const std::size_t columns = series.columns().size();
    if (!series.empty()) f.write("/scene/series", rows, {series.rows().size(), columns}, "SI");
    f.set_attribute("/scene", "origin_step", static_cast<std::int64_t>(run.origin_step));
    if (run.save_scene) run.save_scene(f);
    f.close();
  }
  std::filesystem::rename(temporary, path);
}

}  // namespace

long steps_in(double seconds, double dt) {
  return std::max(1L, static_cast<long>(std::llround(seconds / dt)));
}

TimeSeries read_scene_series(const Hdf5File& f, std::vector<TimeSeriesColumn> columns) {
  TimeSeries series(columns);
  if (!f.exists("/scene/series")) return series;
  const auto dims = f.dims("/scene/series");
  if (dims.size() != 2 || dims[1] != columns.size())
    throw std::runtime_error(f.path().string() + ": /scene/series has another column count than "
                             "this scene (" + std::to_string(columns.size()) + ")");
  const auto data = f.read<double>("/scene/series");
  for (std::size_t r = 0; r < dims[0]; ++r)
    series.add_row(std::vector<double>(data.begin() + static_cast<std::ptrdiff_t>(r * dims[1]),
                                       data.begin() + static_cast<std::ptrdiff_t>((r + 1) * dims[1])));
  return series;
}

DemSceneResult run_dem_scene(DemEngine& engine, const SimulationRequest& request,
                             const DemSceneRun& run) {
  std::ostringstream discard;
  std::ostream& log = request.log ? *request.log : discard;
  engine.prepare(log);
  const auto start = std::chrono::steady_clock::now();
  DemSceneResult result;
  result.series = run.previous.columns().empty() ? TimeSeries(run.columns) : run.previous;
  const double dt = engine.time_step();
  const long end_step = run.origin_step + static_cast<long>(std::ceil(run.duration / dt - 1e-9));
  const long sample_every = steps_in(run.sample_interval, dt);
  const std::filesystem::path checkpoint = request.out / "checkpoint.h5";

  std::optional<ParticleSnapshots> snapshots;
  long snapshot_every = 0;
  if (run.snapshot_interval > 0.0) {
    snapshot_every = steps_in(run.snapshot_interval, dt);
    // A restarted run keeps the first part's file and writes its own beside it.
    const std::string name = engine.step() > run.origin_step && !request.restart.empty()
                                 ? "particles_from_step_" + std::to_string(engine.step()) + ".h5"
                                 : "particles.h5";
    snapshots.emplace(request.out / name, snapshot_every);
  }
  char line[300];
  std::snprintf(line, sizeof line,
                "run: from t = %.4g s (step %ld) to at most step %ld (%.4g s after the origin), "
                "samples every %ld steps (%.3g s), snapshots %s\n",
                engine.time(), engine.step(), end_step, run.duration, sample_every,
                sample_every * dt,
                snapshot_every > 0 ? ("every " + std::to_string(snapshot_every) + " steps").c_str()
                                   : "off");
  log << line;

  auto due_sample = [&](long step) { return (step - run.origin_step) % sample_every == 0; };
  auto take_sample = [&] {
    result.series.add_row(run.sample(engine));
    if (run.stop) result.stop_reason = run.stop(engine, result.series);
  };
  if (snapshots) snapshots->write_if_due(engine.particles(), engine.time(), engine.step());
  if (request.restart.empty() && due_sample(engine.step())) take_sample();

  ProgressLine progress = ProgressLine::for_terminal(
      run.label, static_cast<double>(end_step - engine.step()) * dt, "s", !request.progress);
  const long first_step = engine.step();
  while (engine.step() < end_step && result.stop_reason.empty()) {
    if (interrupt_requested()) {
      result.end = SimulationEnd::interrupted;
      break;
    }
    const long s = engine.step();
    long next = std::min(end_step, s + kMaxChunk);
    next = std::min(next, s + sample_every - ((s - run.origin_step) % sample_every + sample_every) % sample_every);
    if (snapshot_every > 0) next = std::min(next, s + snapshot_every - s % snapshot_every);
    engine.run_steps(std::max(1L, next - s));
    if (snapshots) snapshots->write_if_due(engine.particles(), engine.time(), engine.step());
    if (due_sample(engine.step())) take_sample();
    progress.update(static_cast<double>(engine.step() - first_step) * dt);
  }
  progress.finish();
  write_scene_checkpoint(engine, checkpoint, result.series, run);
  if (snapshots && snapshots->count() > 0) {
    result.files.push_back(snapshots->hdf5_path());
    result.files.push_back(snapshots->xdmf_path());
  }
  result.files.push_back(checkpoint);
  result.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (result.end == SimulationEnd::interrupted)
    log << "run: interrupted at t = " << engine.time() << " s; checkpoint " << checkpoint.string() << '\n';
  else if (!result.stop_reason.empty())
    log << "run: ended at t = " << engine.time() << " s: " << result.stop_reason << '\n';
  log << engine.performance_report();
  return result;
}

SimulationOutcome interrupted_while_filling(const std::string& what) {
  SimulationOutcome out;
  out.end = SimulationEnd::interrupted;
  VerdictBuilder v;
  v.note("interrupted while filling " + what + ": no checkpoint was written, run again");
  out.record.verdict = v.verdict();
  return out;
}

}  // namespace feedflow
