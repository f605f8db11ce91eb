#!/bin/sh
# The slot trust region (slot_trust, bench_strain_driver's 8th field) against the full move,
# with the anchors' secant (friction_tangent 0) and the law's tangent (1): the 9 s flat road at
# 5 ms and 1 ms, backward Euler. From build/tests/core of a Release build, CS_SOURCE_DIR the
# worktree's root. Pass counts and rejected steps are deterministic.
K=${KEEP:-/tmp/passes_keep}/trust; mkdir -p $K
CS_BENCH_KEEP=$K ${BENCH:-./bench_strain_driver} 9 strain:3:0.005:1:0:1:1:1 strain:3:0.005:1:0:1:0:1 \
  strain:3:0.005:1:0:1:1:0
CS_BENCH_KEEP=$K ${BENCH:-./bench_strain_driver} 9 strain:3:0.001:1:0:1:0:0 strain:3:0.001:1:0:1:1:0 \
  strain:3:0.001:1:0:1:1:1 strain:3:0.001:1:0:1:0:1
