#!/bin/bash
# Two or more builds of feedflow_benchmarks side by side on DemBed30k, one thread: ROUNDS rounds,
# each build in turn per round, each run 15 repetitions of one iteration (100 steps); prints the
# best and the median particle-steps per second of each run. On a shared machine noise only slows
# a run down, so best and median of alternated runs compare builds where single runs cannot.
#   tests/benchmarks/compare_builds.sh ROUNDS LAW BENCHMARK_BINARY...
#   tests/benchmarks/compare_builds.sh 3 1 OLD/feedflow_benchmarks build/tests/feedflow_benchmarks  # OLD: another build
# LAW: 0 hertz + mindlin + cdt, 1 hysteretic_nonlinear2 + history + cdt (dem_bench.cpp).
set -eu
if [ $# -lt 3 ]; then
  echo "usage: $0 ROUNDS LAW BENCHMARK_BINARY..." >&2
  exit 2
fi
rounds=$1 law=$2
shift 2
printf '%-5s %-50s %10s %10s\n' round binary best_M median_M
for r in $(seq "$rounds"); do
  for b in "$@"; do
    values=$(OMP_NUM_THREADS=1 "$b" --benchmark_filter="DemBed30k/law:$law/threads:1" \
      --benchmark_repetitions=15 --benchmark_min_time=0.01 2>/dev/null |
      grep -E "^DemBed30k/law:$law/threads:1/min_time:[0-9.]*/real_time " |
      sed -E 's/.*particle_steps_per_s=([0-9.]+)M.*/\1/' | sort -g)
    n=$(echo "$values" | wc -l)
    printf '%-5s %-50s %10s %10s\n' "$r" "$b" "$(echo "$values" | tail -1)" \
      "$(echo "$values" | sed -n "$(((n + 1) / 2))p")"
  done
done
