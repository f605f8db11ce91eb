#!/bin/sh
# runs.sh: the runs of this folder besides bench.sh, in the order they were made (one at a
# time), from the worktree after a build; tracks into /work/rom_data/adastep (not committed:
# this regenerates them, ~3 min of CPU on a quiet machine). The paper's table's references (the
# rod at 16 elements and 0.25 ms, at 32 and 0.5 ms) and the strain level's fixed 0.5 ms run of
# the sixth session are branch strainacc's (/work/rom_data/strainacc: its runs.sh makes them).
set -e
H=docs/bench/adastep_2026-12-06g
C=$H/crun.sh
# the fixed step against main's binary (flat road 1 s, the level's default 0.5 ms)
CRAWLSIM=/work/main/build/tools/crawlsim $C fix_main_f1 --scene flat-road --legs strain --t-end 1
$C fix_mine_f1 --scene flat-road --legs strain --t-end 1
/usr/bin/python3 $H/same.py /work/rom_data/adastep/fix_main_f1.h5 /work/rom_data/adastep/fix_mine_f1.h5
# the tolerance: flat road (9.5 s) and the obstacle's first 4 s (5e-4 and 1e-3: bench.sh)
for t in 0.01; do
  $C ada_flat_t$t --scene flat-road --legs strain --strain-step adaptive --step-tol $t
done
for t in 0.01 0.003; do
  $C ada_obst_t$t --scene obstacle --legs strain --strain-step adaptive --step-tol $t --t-end 4
done
# the paper's table (paper, 9 s) and earth with it (the fall), at the adaptive default
$C ada_paper --scene flat-road --legs strain --strain-step adaptive --gait gaits/flat_road_paper.csv --conditions paper --t-end 9
$C fix_paper_05ms --scene flat-road --legs strain --gait gaits/flat_road_paper.csv --conditions paper --t-end 9
# (ada_earth_v1.log: the same before a step the stages halved proposed at most its half)
$C ada_earth2 --scene flat-road --legs strain --strain-step adaptive --conditions earth --gait gaits/flat_road_paper.csv --t-end 1.5
$C fix_earth_05ms --scene flat-road --legs strain --conditions earth --gait gaits/flat_road_paper.csv --t-end 1.5
# the two sweep points rerun after the state check's fix (section "Found on the way")
$C ada_obst_t0.0003 --scene obstacle --legs strain --strain-step adaptive --step-tol 0.0003 --t-end 4
$C ada_flat_t0.0003 --scene flat-road --legs strain --strain-step adaptive --step-tol 0.0003
