#!/bin/sh
# The active set's measurements (docs/notes/strain_leg.md, "Active set"), from build/tests/core
# of a Release build, CS_SOURCE_DIR the worktree's root. One process per line: the ratios are
# measured under the same load; pass counts and rejected steps are deterministic.
#   ACTIVE 1 (default) / 0: the strain level's setting active_set (bench_strain_driver's 6th field)
K=${KEEP:-/tmp/ghost_keep}; mkdir -p $K $K/tol6 $K/tol5
./bench_strain_driver 1 strain:3:0.005:1:0:1 strain:3:0.005:1:0:0
CS_BENCH_KEEP=$K ./bench_strain_driver 9 strain:3:0.005:1:0:1 strain:3:0.005:1:0:0 \
  strain:3:0.001:1:0:1 strain:3:0.001:1:0:0
CS_BENCH_KEEP=$K/tol6 ./bench_strain_driver 9 strain:3:0.005:1:1e-6:1
CS_BENCH_KEEP=$K/tol5 ./bench_strain_driver 9 strain:3:0.005:1:1e-5:1
C=$(dirname "$0")/../strain_driver_2026-12-05/compare.py
/usr/bin/python3 $C $K/strain_3_0.005_1.h5 $K/tol6/strain_3_0.005_1.h5 \
  $K/tol5/strain_3_0.005_1.h5 $K/strain_3_0.005_1_noactive.h5
/usr/bin/python3 $C $K/strain_3_0.001_1_noactive.h5 $K/strain_3_0.001_1.h5 \
  $K/strain_3_0.005_1.h5 $K/strain_3_0.005_1_noactive.h5
