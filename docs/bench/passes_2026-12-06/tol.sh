#!/bin/sh
# tree_tol against the noise floor (docs/notes/strain_leg.md, "Passes per step"): the 9 s flat
# road at the level's default 1 ms and at 5 ms, backward Euler, tree_tol 1e-7 / 1e-6 / 1e-5 mm,
# and the noise floor at tol 1e-7: the pneumatics 10x tighter (CS_BENCH_PTOL=0.1), the step
# +-10 %. From build/tests/core of a Release build (BENCH: the binary), CS_SOURCE_DIR the
# worktree's root; tracks compared by ../strain_driver_2026-12-05/compare.py.
B=${BENCH:-./bench_strain_driver}
K=${KEEP:-/tmp/passes_keep}
for d in t7 t6 t5 p01 h09 h11; do mkdir -p $K/$d; done
CS_BENCH_KEEP=$K/t6 $B 9 strain:3:0.001:1:1e-6 strain:3:0.005:1:1e-6
CS_BENCH_KEEP=$K/t7 $B 9 strain:3:0.001:1:1e-7
CS_BENCH_KEEP=$K/t5 $B 9 strain:3:0.001:1:1e-5 strain:3:0.005:1:1e-5
CS_BENCH_PTOL=0.1 CS_BENCH_KEEP=$K/p01 $B 9 strain:3:0.001:1:1e-7 strain:3:0.005:1:1e-7
CS_BENCH_KEEP=$K/h09 $B 9 strain:3:0.0009:1:1e-7 strain:3:0.0045:1:1e-7
CS_BENCH_KEEP=$K/h11 $B 9 strain:3:0.0011:1:1e-7 strain:3:0.0055:1:1e-7
CS_BENCH_KEEP=$K/t7 $B 9 strain:3:0.005:1:1e-7
