#!/bin/sh
# run_tracks.sh H5DIR: the 9 s flat road and the obstacle's first 4 s at 5 and 1 ms, the
# default (a new iteration matrix every step) and keep_matrix 0.05, one process per step and
# scene (their CPU ratio under the same load); run from build/tests/core with CS_SOURCE_DIR the
# worktree. Tracks kept in H5DIR (CS_BENCH_KEEP); compare with
# docs/bench/onepass_2026-12-06/tracks.py.
export CS_BENCH_KEEP=$1
mkdir -p "$1"
uptime
for H in 0.005 0.001; do
  nice -n 5 ./bench_strain_driver 9 strain:3:$H:1:0:-1:-1:-1:0 strain:3:$H:1:0:-1:-1:-1:0.05
  CS_BENCH_SCENE=obstacle nice -n 5 ./bench_strain_driver 4 strain:3:$H:1:0:-1:-1:-1:0 strain:3:$H:1:0:-1:-1:-1:0.05
done
uptime
