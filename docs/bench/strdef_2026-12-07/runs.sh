#!/bin/sh
# runs.sh: the tolerance study's first runs, one after the other (nice 5, resumable: crun.sh skips a
# run whose log has its verdict); from the worktree; stopped after its first five runs (queue.sh). HDF5 files in /work/rom_data/strdef (not
# committed: this regenerates them; each 5-60 CPU s, the rod reference ~4-5 CPU min).
# Scene defaults: the obstacle under `paper` with gaits/obstacle.csv and its gate, to 8 s
# (past the 7.47 s where the fixed 0.5 ms falls); the flat road under `paper`, its gait's 9.5 s.
H=$(dirname "$0")
C=$H/crun.sh
A="--legs strain --strain-step adaptive"
O="--scene obstacle --t-end 8"
F="--scene flat-road"
for t in 5e-4 2.5e-4 1e-3 2e-4; do $C obst_a$t $O $A --step-tol $t; done
$C obst_f0.5ms $O --legs strain --strain-step fixed --dt 0.0005
for t in 5e-4 2.5e-4 1e-3 2e-4; do $C flat_a$t $F $A --step-tol $t; done
$C flat_f0.5ms $F --legs strain --strain-step fixed --dt 0.0005
# the reference: the rod at 32 elements per segment, 0.25 ms (as tools/bench_levels.py
# --ref-links 32 makes the 4 s one), checkpointed every simulated second
$C obst_rod32 $O --legs rod --links 32 --macro-steps 1 --dt 0.00025 \
  --checkpoint /work/rom_data/strdef/obst_rod32.ckpt --checkpoint-every 1
$C obst_f0.25ms $O --legs strain --strain-step fixed --dt 0.00025
$C flat_f0.25ms $F --legs strain --strain-step fixed --dt 0.00025
