#!/bin/sh
# run_obstacle.sh: the obstacle's first 4 s (its scene's defaults under `paper`), backward Euler
# converged and one_pass 1 at 1, 2.5 and 5 ms; from build/tests/core, CS_SOURCE_DIR the worktree,
# CS_BENCH_KEEP a directory for the tracks
uptime
for H in 0.001 0.0025 0.005; do
  CS_BENCH_SCENE=obstacle nice -n 5 ./bench_strain_driver 4 strain:3:$H:1 strain:3:$H:1:0:-1:-1:-1:1
done
uptime
