// One sweep point as `feedflow sweep` answers it in process (override, load from the parsed
// case, design check without charts): the points/s a sweep reaches on one thread.
#include <benchmark/benchmark.h>

#include <filesystem>

#include "designer/sweep/sweep_grid.hpp"

namespace {

void SweepPointPilotHopper(benchmark::State& state) {
  feedflow::SweepRequest r;
  const std::filesystem::path cases = std::filesystem::path(FEEDFLOW_SOURCE_DIR) / "cases";
  r.parsed = feedflow::parse_case((cases / "pilot_hopper.toml").string());
  r.materials = feedflow::MaterialLibrary::standard(cases);
  r.axes = {feedflow::parse_sweep_axis("hopper.semi_angle=15..40deg:20"),
            feedflow::parse_sweep_axis("hopper.outlet_width=20..100mm:50")};
  const std::size_t n = feedflow::grid_size(r.axes);
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(feedflow::answer_point(r, feedflow::grid_index(r.axes, i)));
    i = (i + 1) % n;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(SweepPointPilotHopper)->Unit(benchmark::kMicrosecond);

}  // namespace
