#!/bin/sh
# Every leg level on the flat road (scene defaults: 23-mode symmetric-mesh table under rbf-pair,
# gaits/flat_road_rod.csv, paper), 9 s, in ONE process so the CPU ratios share the load; each
# run's file is kept (CS_BENCH_KEEP) for its track against the converged rod (16 elements per
# segment, 0.25 ms): compare.py. From the repository root, after the Release build.
set -e
mkdir -p build/levels_one
cd build/tests/core
CS_SOURCE_DIR=../../.. CS_BENCH_KEEP=../../levels_one nice -n 10 ./bench_strain_driver 9 \
  rod:2 rod:4 rod:8 strain:3:0.001:1 strain:3:0.005:2 prb:2 prb:4 prb:8 rod:16:0.00025
