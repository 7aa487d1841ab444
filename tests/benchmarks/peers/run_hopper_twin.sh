#!/bin/sh
# The pilot hopper slab twin (issue 23): our run, its fill at the opening exported for LIGGGHTS,
# and the LIGGGHTS run from it, one after the other on one core each (OMP_NUM_THREADS=1, one MPI
# rank). Run from the repository root after building build/feedflow. Prints the wall time of
# each; the rates and windows are measured from $OUT/ours/results.json and
# $OUT/liggghts_series.txt (README.md, "Pilot hopper slab twin").
#   tests/benchmarks/peers/run_hopper_twin.sh
#   TEND=1.5 OUT=/tmp/feedflow_twin tests/benchmarks/peers/run_hopper_twin.sh
set -eu
here=$(cd "$(dirname "$0")" && pwd)
OUT=${OUT:-/tmp/feedflow_twin}
TEND=${TEND:-1.5}          # [s] of LIGGGHTS discharge after the opening
mkdir -p "$OUT"
rm -rf "$OUT/ours"
start=$(date +%s)
OMP_NUM_THREADS=1 OMP_WAIT_POLICY=passive build/feedflow simulate cases/pilot_hopper.toml \
  --solver dem --set dem.normal_law=hertz --set dem.slab_depth=3.3mm \
  --set dem.slab_faces=frictionless --out "$OUT/ours" > "$OUT/ours.log"
echo "ours: $(($(date +%s) - start)) s wall; $(grep 'mass flow rate slab' "$OUT/ours/results.txt")"
# The run's time step (the first snapshot's time over its step), and the fill at the opening.
group=$(h5dump -n "$OUT/ours/particles.h5" | awk '/group +\/snapshots\/step_/ {print $2; exit}')
t=$(h5dump -m %.17g -a "$group/time" "$OUT/ours/particles.h5" | awk '/\(0\)/ {print $2}')
dt=$(python3 -c "print(repr($t / int('${group##*step_}')))")
python3 "$here/snapshot_to_data.py" "$OUT/ours/particles.h5" "$OUT/hopper_slab.data" \
  --density 390 --box -0.306 0.306 -0.0045 0.0078 -0.1 0.778
python3 "$here/wedge_stl.py" --semi-angle 30 --outlet 0.06 --bin 0.6 --y0 -0.003 --y1 0.0063 \
  > "$OUT/wedge.stl"
start=$(date +%s)
(cd "$OUT" && mpirun --allow-run-as-root -np 1 liggghts -in "$here/in.hopper_slab.liggghts" \
  -var data hopper_slab.data -var stl wedge.stl -var dt "$dt" -var tend "$TEND" -var every 625 \
  -var series liggghts_series.txt > liggghts.log)
echo "liggghts: $(($(date +%s) - start)) s wall, dt $dt s; series in $OUT/liggghts_series.txt"
