#!/bin/sh
# run_tracks.sh BIN OUT [SPEC...]: the flat road (9 s) and the obstacle's first 4 s
# (CS_BENCH_SCENE=obstacle) by bench_strain_driver BIN, one SPEC after the other, each run's
# file kept in OUT (CS_BENCH_KEEP), the bench's lines printed with uptime before each; then
# track_err.py against the rod-32 references (REF, default /work/rom_data/levels_ref). Run from
# the worktree's root. SPEC as bench_strain_driver's (strain:LINKS:DT:ORDER:...:SUB:CALQ).
root=$(pwd); here=$(cd "$(dirname "$0")" && pwd); bin=$1; out=$2; shift 2
REF=${REF:-/work/rom_data/levels_ref}
mkdir -p "$out"
export CS_SOURCE_DIR=$root
cd build/tests/core || exit 1
for SPEC in "$@"; do
  for S in flat-road obstacle; do
    T=9; [ $S = obstacle ] && T=4
    echo "== $S $SPEC T=$T $(uptime)"
    CS_BENCH_SCENE=$S CS_BENCH_KEEP=$out nice -n 5 "$bin" "$T" "$SPEC" | grep -E "^(flat|obst)|tree:|basis:"
  done
done
/usr/bin/python3 "$here/track_err.py" "$REF" "$out"/flat-road_*.h5 "$out"/obstacle_*.h5
