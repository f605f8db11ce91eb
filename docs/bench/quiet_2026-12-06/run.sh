#!/bin/sh
# The strain and rod levels' real-time factors on a quiet machine (load ~1), one process per
# list so the ratios share the load; from the repository root after the Release build.
# Measured 2026-12-06 07:52-07:56 UTC on the project's 2-core AMD EPYC VM (docs/results.md).
set -e
cd build/tests/core
export CS_SOURCE_DIR=../../..
./bench_strain_driver 9 strain:3:0.001:1 strain:3:0.005:1 rod:4 rod:8 > ../../../docs/bench/quiet_2026-12-06/flat_road.txt
CS_BENCH_SCENE=obstacle ./bench_strain_driver 4 strain:3:0.001:1 strain:3:0.005:1 > ../../../docs/bench/quiet_2026-12-06/obstacle_4s.txt
./bench_strain_driver 9 strain:3:0.005:2 strain:3:0.0025:2 strain:3:0.0025:1 > ../../../docs/bench/quiet_2026-12-06/flat_road_bdf2_2.5ms.txt
cd ../../..
./build/tools/crawlsim run --scene obstacle --legs strain --out build/obstacle_strain.h5 > docs/bench/quiet_2026-12-06/obstacle_strain_whole.txt 2>&1 || true
