// Whole design checks as `feedflow design` runs them (estimates, bands over the material's
// uncertainty, verdict and report charts), case already loaded.
#include <benchmark/benchmark.h>

#include "designer/case/case_loader.hpp"
#include "designer/design/design_check.hpp"

namespace {

using feedflow::Case;
using feedflow::ModelChoices;

void run(benchmark::State& state, const char* file, std::vector<std::string> models) {
  const Case c = feedflow::load_case(std::string(FEEDFLOW_SOURCE_DIR) + "/" + file);
  const ModelChoices choices = ModelChoices::parse(models);
  for (auto _ : state) benchmark::DoNotOptimize(feedflow::design_check(c, choices));
}

void BM_DesignCheckHopper(benchmark::State& s) { run(s, "cases/pilot_hopper.toml", {}); }
void BM_DesignCheckHopperRsf(benchmark::State& s) { run(s, "cases/pilot_hopper.toml", {"hopper.flow_factor=rsf"}); }
void BM_DesignCheckChuteL0(benchmark::State& s) { run(s, "cases/inclined_plane_29_5.toml", {"chute.deposit=none"}); }
void BM_DesignCheckChuteWithL1(benchmark::State& s) { run(s, "cases/inclined_plane_29_5.toml", {}); }
void BM_DesignCheckDrum(benchmark::State& s) { run(s, "cases/rotating_drum_20rpm.toml", {}); }

}  // namespace

BENCHMARK(BM_DesignCheckHopper)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DesignCheckHopperRsf)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DesignCheckChuteL0)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DesignCheckChuteWithL1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DesignCheckDrum)->Unit(benchmark::kMillisecond);
