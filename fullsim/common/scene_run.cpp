#include "fullsim/common/scene_run.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "models/os/interrupt_request.hpp"
#include "models/units/quantity_format.hpp"

namespace feedflow {
namespace {

using Clock = std::chrono::steady_clock;
constexpr double kNever = std::numeric_limits<double>::infinity();

std::string seconds(double t) {
  char text[40];
  std::snprintf(text, sizeof text, "%.6g s", t);
  return text;
}

double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

std::string column_names(const std::vector<TimeSeriesColumn>& columns) {
  std::string names;
  for (const auto& c : columns) (names += names.empty() ? "" : ",") += c.name;
  return names;
}

// The stepper's state and the /scene group (series and the scene's own data).
void write_checkpoint(const Stepper& stepper, const std::filesystem::path& path,
                      const TimeSeries& series, const SceneRunOptions& o) {
  write_whole_checkpoint(path, stepper.writes_files(), [&](Hdf5File& f) {
    stepper.write_checkpoint(f);
    f.create_group("/scene");
    f.set_attribute("/scene", "series_columns", column_names(series.columns()));
    std::vector<double> rows;
    for (const auto& r : series.rows()) rows.insert(rows.end(), r.begin(), r.end());
    if (!series.empty()) f.write("/scene/series", rows, {series.rows().size(), series.columns().size()}, "SI");
    if (o.save_scene) o.save_scene(f);
    return true;
  });
}

// The first snapshot time after the current one: a multiple of `interval` from `origin`.
double next_snapshot_after(const Stepper& stepper, double origin, double interval) {
  double m = std::floor((stepper.time() - origin) / interval + 1e-9) + 1.0;
  while (stepper.reached(origin + m * interval)) m += 1.0;
  return origin + m * interval;
}

}  // namespace

bool write_whole_checkpoint(const std::filesystem::path& path, bool on_disk,
                            const std::function<bool(Hdf5File&)>& write) {
  namespace fs = std::filesystem;
  if (!on_disk) {
    Hdf5File f(path, Hdf5File::Mode::scratch);
    return write(f);
  }
  const fs::path temporary = path.string() + ".tmp" + std::to_string(::getpid());
  try {
    // A file that cannot be created still gets the state written (in memory), so an engine
    // shared among processes gathers it on every one before this one reports the failure.
    std::optional<Hdf5File> f;
    std::string cannot;
    try {
      f.emplace(temporary, Hdf5File::Mode::create);
    } catch (const std::runtime_error& e) {
      cannot = e.what();
      f.emplace(temporary, Hdf5File::Mode::scratch);
    }
    const bool keep = write(*f);
    if (!cannot.empty()) throw std::runtime_error(cannot);
    f->close();
    if (!keep) {
      fs::remove(temporary);
      return false;
    }
  } catch (const std::exception& e) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw std::runtime_error("cannot write the checkpoint " + path.string() + ": " + e.what());
  }
  std::error_code ec;
  fs::rename(temporary, path, ec);
  if (ec) {
    fs::remove(temporary, ec);
    throw std::runtime_error("cannot write the checkpoint " + path.string() + ": " + ec.message());
  }
  return true;
}

std::filesystem::path scene_checkpoint_path(const std::filesystem::path& folder) {
  return folder / "checkpoint.h5";
}

TimeSeries restore_scene_run(Stepper& stepper, const Hdf5File& f,
                             const std::vector<TimeSeriesColumn>& columns) {
  stepper.restore(f);
  TimeSeries series(columns);
  if (!f.exists("/scene"))
    throw std::runtime_error(f.path().string() + " has no /scene group: not a checkpoint of a "
                             "feedflow scene run");
  const std::string saved = f.string_attribute("/scene", "series_columns");
  if (saved != column_names(columns))
    throw std::runtime_error(f.path().string() + " holds the series of another scene (columns " +
                             saved + ", this scene's " + column_names(columns) + ")");
  if (!f.exists("/scene/series")) return series;
  const auto dims = f.dims("/scene/series");
  if (dims.size() != 2 || dims[1] != columns.size())
    throw std::runtime_error(f.path().string() + ": /scene/series has another column count than "
                             "this scene (" + std::to_string(columns.size()) + ")");
  const auto data = f.read<double>("/scene/series");
  for (std::size_t r = 0; r < dims[0]; ++r) {
    const auto row = data.begin() + static_cast<std::ptrdiff_t>(r * dims[1]);
    series.add_row(std::vector<double>(row, row + static_cast<std::ptrdiff_t>(dims[1])));
  }
  return series;
}

SceneRunResult run_scene(Stepper& stepper, const SceneRunOptions& o) {
  std::ostringstream discard;
  std::ostream& log = o.log ? *o.log : discard;
  SilentProgress silent;
  ProgressSink& progress = o.progress ? *o.progress : silent;
  stepper.prepare(log);
  const auto start = Clock::now();
  double snapshot_seconds = 0.0, sample_seconds = 0.0;
  SceneRunResult r;
  r.series = o.previous.columns().empty() ? TimeSeries(o.columns) : o.previous;
  const bool restarted = !o.restart.empty();

  const double sample_every = stepper.whole_steps(o.sample_interval, StepRounding::nearest);
  // Every sample inside the asked duration is taken: a sample interval rounded up to whole steps
  // can put the last one past the duration's last step, so the run then ends on that sample.
  const double in_samples = o.sample_interval > 0.0 ? std::round(o.duration / o.sample_interval) : 0.0;
  const bool whole_samples = in_samples > 0.0 && std::abs(o.duration / o.sample_interval - in_samples) < 1e-9 * in_samples;
  const double last_sample = whole_samples ? in_samples * sample_every : 0.0;
  const double on_grid = stepper.whole_steps(o.duration, StepRounding::up);
  const double run_for = last_sample > on_grid * (1.0 + 1e-9) ? last_sample : on_grid;  // not for round-off
  // Snapshots count from the sample origin; an interval of whole sample intervals is planned as
  // that many sample steps, so each snapshot is taken on the step of a row (a snapshot's time in
  // ParaView is a time in the series).
  const double per_sample = o.sample_interval > 0.0 ? o.snapshot_interval / o.sample_interval : 0.0;
  const bool on_rows =
      per_sample >= 1.0 && std::abs(per_sample - std::round(per_sample)) < 1e-9 * per_sample;
  const double snapshot_every =
      o.snapshot_interval <= 0.0 ? 0.0
      : on_rows                  ? std::round(per_sample) * sample_every
                                 : stepper.whole_steps(o.snapshot_interval, StepRounding::nearest);
  const auto origin = [&] { return o.origin ? o.origin : stepper.event_started_at(); };
  const auto end_time = [&] {
    const auto t0 = origin();
    return t0 ? *t0 + run_for : kNever;
  };
  const auto next_sample = [&] {
    const double k = static_cast<double>(r.series.rows().size()) + (o.sample_at_origin ? 0.0 : 1.0);
    return o.sample_origin + k * sample_every;
  };
  const auto take_due_samples = [&] {
    const auto t = Clock::now();
    while (stepper.reached(next_sample())) {
      r.series.add_row(o.sample());
      if (o.stop && r.stop_reason.empty()) r.stop_reason = o.stop(r.series);
    }
    sample_seconds += seconds_since(t);
  };

  std::unique_ptr<SnapshotWriter> snapshots;
  double snapshot_at = kNever;
  if (snapshot_every > 0.0) {
    snapshots = stepper.snapshot_writer(o.out, restarted);
    if (!restarted) snapshots->write();
    snapshot_at = next_snapshot_after(stepper, o.sample_origin, snapshot_every);
  }
  log << "run: from t = " << seconds(stepper.time()) << " to " << seconds(run_for) << " after the "
      << (origin() ? "origin at t = " + seconds(*origin()) : std::string("scene's event"))
      << ", samples every " << seconds(sample_every) << ", snapshots "
      << (snapshot_every > 0.0 ? "every " + seconds(snapshot_every) : std::string("off")) << '\n';

  take_due_samples();
  const double t_start = stepper.time();
  const auto planned_end = [&] {
    const double end = end_time();
    return end < kNever ? end : o.latest_origin + run_for;
  };
  const double planned = planned_end() - t_start;
  auto last_checkpoint = Clock::now();
  double periodic_seconds = 0.0;
  long periodic_checkpoints = 0;
  progress.begin(o.label, planned, "s");
  while (true) {
    const double end = end_time();
    if (stepper.reached(end)) break;
    if (!r.stop_reason.empty()) {
      r.end = RunEnd::stopped;
      break;
    }
    if (stepper.raised_on_any(interrupt_requested()) && stepper.checkpoint_ready()) {  // else after the next steps
      r.end = RunEnd::interrupted;
      break;
    }
    stepper.advance_to(std::min({next_sample(), snapshot_at, end}), o.steps_between_checks);
    if (snapshots && stepper.reached(snapshot_at)) {
      const auto t = Clock::now();
      snapshots->write();
      snapshot_at = next_snapshot_after(stepper, o.sample_origin, snapshot_every);
      snapshot_seconds += seconds_since(t);
    }
    take_due_samples();
    // Every process agrees on the periodic checkpoint (their clocks differ); a failed write
    // (a full disk) stops the run as the end's would.
    const bool due =
        o.checkpoint_every > 0.0 && seconds_since(last_checkpoint) >= o.checkpoint_every;
    if (o.checkpoint_every > 0.0 && stepper.raised_on_any(due) && stepper.checkpoint_ready()) {
      const auto t = Clock::now();
      std::optional<std::string> failure;
      try {
        write_checkpoint(stepper, scene_checkpoint_path(o.out), r.series, o);
      } catch (const std::runtime_error& e) {
        failure = e.what();
      }
      if (auto agreed = stepper.agreed_failure(failure)) throw std::runtime_error(*agreed);
      periodic_seconds += seconds_since(t);
      ++periodic_checkpoints;
      last_checkpoint = Clock::now();
    }
    // Done in the terms of the first plan (a scene event moves the end).
    progress.update((stepper.time() - t_start) * planned / std::max(planned_end() - t_start, 1e-300));
  }
  progress.finish();
  const auto checkpoint_start = Clock::now();
  const std::filesystem::path checkpoint = scene_checkpoint_path(o.out);
  std::optional<std::string> failure;
  try {
    write_checkpoint(stepper, checkpoint, r.series, o);
  } catch (const std::runtime_error& e) {
    failure = e.what();
  }
  if (auto agreed = stepper.agreed_failure(failure)) throw std::runtime_error(*agreed);
  const double checkpoint_seconds = seconds_since(checkpoint_start);
  if (snapshots)
    for (auto& f : snapshots->files()) r.files.push_back(std::move(f));
  if (stepper.writes_files()) r.files.push_back(checkpoint);
  r.wall_seconds = seconds_since(start);

  if (r.end == RunEnd::interrupted)
    log << "run: interrupted at t = " << seconds(stepper.time()) << "; checkpoint " << checkpoint.string() << '\n';
  else if (r.end == RunEnd::stopped)
    log << "run: ended at t = " << seconds(stepper.time()) << ": " << r.stop_reason << '\n';
  r.performance = stepper.performance();
  r.performance.add_phase_time("sampling", sample_seconds);
  r.performance.add_phase_time("snapshots", snapshot_seconds);
  r.performance.add_phase_time("checkpoint", checkpoint_seconds + periodic_seconds);
  if (periodic_checkpoints > 0)
    r.performance.add_figure("checkpoints on the way",
                             std::to_string(periodic_checkpoints) + ", every " +
                                 format_quantity(o.checkpoint_every, "s") + " of wall time");
  r.performance.set_wall_seconds(r.wall_seconds + o.setup_seconds);
  if (o.setup_seconds > 0.0)
    r.performance.add_figure(o.setup_name + " (before the run)",
                             format_quantity(o.setup_seconds, "s") + " of the wall time");
  log << r.performance.render();
  return r;
}

}  // namespace feedflow
