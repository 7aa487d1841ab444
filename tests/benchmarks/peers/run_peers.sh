#!/bin/sh
# Runs the DemBed30k bed in LIGGGHTS 3.8 and LAMMPS (Debian packages `liggghts`, `lammps`; both
# parallelise with MPI ranks, the Debian LAMMPS has no OPENMP package) on 1 and 2 ranks, REPEAT
# times each, and prints particle-steps per second of the timed run (after NSETTLE settling steps).
#   tests/benchmarks/peers/run_peers.sh            # defaults below
#   DT=3.2e-5 NSETTLE=1500 NSTEPS=1000 REPEAT=2 RANKS="1 2" tests/benchmarks/peers/run_peers.sh
#   TILT=30 tests/benchmarks/peers/run_peers.sh    # the chute (DemChute30k): gravity tilted 30 deg
# Logs go to $OUT (default /tmp/feedflow_peers).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
DT=${DT:-3.2e-5}          # 0.2 x Rayleigh time of the pine grain (1.62e-4 s)
NSETTLE=${NSETTLE:-1500}  # as dem_bench.cpp
NSTEPS=${NSTEPS:-1000}
TILT=${TILT:-0}            # gravity tilt from -z toward +x [deg]; 30: the chute
REPEAT=${REPEAT:-2}
RANKS=${RANKS:-"1 2"}
PEERS=${PEERS:-"liggghts lammps"}
OUT=${OUT:-/tmp/feedflow_peers}
mkdir -p "$OUT"
mpi="mpirun --oversubscribe"
[ "$(id -u)" = 0 ] && mpi="$mpi --allow-run-as-root"
printf '%-9s %5s %3s %12s %14s %8s %10s\n' peer ranks rep loop_time_s particle_steps/s load1 vx_m/s
for peer in $PEERS; do
  case $peer in liggghts) exe=liggghts ;; lammps) exe=lmp ;; esac
  for np in $RANKS; do
    r=1
    while [ "$r" -le "$REPEAT" ]; do
      log="$OUT/log.$peer.np$np.r$r"
      load=$(cut -d' ' -f1 /proc/loadavg)
      $mpi -np "$np" $exe -in "$here/in.bed30k.$peer" -var dt "$DT" -var nsettle "$NSETTLE" \
        -var nsteps "$NSTEPS" -var tilt "$TILT" -log "$log" > "$log.out" 2>&1
      # last "Loop time of T on P procs for N steps with M atoms" line is the timed run
      grep 'Loop time of' "$log" | tail -1 | awk -v peer="$peer" -v np="$np" -v r="$r" -v load="$load" \
        '{t=$4; n=$9; m=$12; printf "%-9s %5s %3s %12.3f %14.4g %8s", peer, np, r, t, m*n/t, load}'
      # mean x velocity (the chute's down-slope speed) at the last thermo line [m/s]
      awk '/^ *Step/{h=1; next} h && $1 ~ /^[0-9]+$/ {v=$4} /Loop time/{h=0} END{printf " %10.4g\n", v}' "$log"
      r=$((r + 1))
    done
  done
done
