#!/bin/bash
# the obstacle's 1-2 s window, tree_skip 0 and 0.1 (bin2)
cd /work/wt-pass15
export CG_OUT=/tmp/pass15/cg CS_BENCH_SCENE=obstacle
CS_BENCH_SKIP=0 docs/bench/speed_2026-12-07/cg.sh /tmp/pass15/bin2/bench_strain_driver base.obst 1 1 strain:2 2.5e-4 1
CS_BENCH_SKIP=0.1 docs/bench/speed_2026-12-07/cg.sh /tmp/pass15/bin2/bench_strain_driver skip.obst 1 1 strain:2 2.5e-4 1
echo cgobst done
