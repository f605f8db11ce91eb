#!/bin/sh
# The friction's tangent (docs/notes/strain_leg.md, "The friction's tangent"), from build/tests/core
# of a Release build, CS_SOURCE_DIR the worktree's root. One process per line: the ratios are
# measured under the same load; pass counts and rejected steps are deterministic.
#   7th field: the strain level's setting friction_tangent, 0 the anchors' secant (default), 1 the tangent
K=${KEEP:-/tmp/ghost2_keep}; mkdir -p $K
./bench_strain_driver 1 strain:3:0.005:1:0:1:0 strain:3:0.005:1:0:1:1        # bench_1s.txt
./bench_strain_driver 1 strain:3:0.001:1:0:1:0 strain:3:0.001:1:0:1:1        # bench_1s_1ms.txt
CS_BENCH_KEEP=$K ./bench_strain_driver 9 strain:3:0.001:1:0:1:0 strain:3:0.001:1:0:1:1  # bench_9s_1ms.txt
/usr/bin/python3 $(dirname "$0")/../strain_driver_2026-12-05/compare.py \
  $K/flat-road_strain_3_0.001_1.h5 $K/flat-road_strain_3_0.001_1_tangent.h5          # tracks_1ms.txt
# (the third lines of bench_1s.txt and bench_1s_1ms.txt: the hybrid "secant only on a slot just
# saturated", FRIC 2 at commit 6fce9d7; bench_1s_cycle.txt's second: the hybrid "tangent until
# a slot crosses the saturation", never committed; both removed, the notes say why)
