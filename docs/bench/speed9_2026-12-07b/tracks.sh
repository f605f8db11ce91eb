#!/bin/sh
# tracks.sh BIN OUT TOL SCENE T SPEC: one run of bench_strain_driver BIN (SCENE flat-road or
# obstacle, T simulated s, SPEC strain:LINKS:DT:...), its file kept in OUT (CS_BENCH_KEEP), the
# adaptive step at TOL mm when TOL > 0 (CS_BENCH_ADAPTIVE); uptime before and after. Compare
# the files with track_err.py REF BASE.h5 NEW.h5 (the first of a scene is the base). Run from
# the worktree's root.
root=$(pwd); bin=$1; out=$2; tol=$3; scene=$4; T=$5; spec=$6
mkdir -p "$out"
export CS_SOURCE_DIR=$root
cd build/tests/core || exit 1
echo "== $bin $scene $spec T=$T tol=$tol $(uptime)"
CS_BENCH_SCENE=$scene CS_BENCH_KEEP=$out CS_BENCH_ADAPTIVE=$tol nice -n 5 "$bin" "$T" "$spec" |
  grep -E "^(flat|obst)|tree:|basis:|window"
echo "   $(uptime)"
