#!/bin/sh
# queue.sh: issue 32's must-show on today's default (strain legs, adaptive 2.5e-4 mm, 2 Magnus
# sub-intervals), one run at a time. The designed gait's references are the quiet run's
# (/work/rom_data/levels_ref9 = docs/bench/quiet8_2026-12-07's rod at 32 elements and 0.25 ms);
# the paper's table needs its own (rod32_paper, rod32_earth). From the worktree.
C=$(dirname "$0")/crun.sh
P=gaits/flat_road_paper.csv
$C rod32_paper --scene flat-road --legs rod --links 32 --macro-steps 1 --dt 0.00025 --gait $P --conditions paper --t-end 9
$C def_paper --scene flat-road --legs strain --gait $P --conditions paper --t-end 9
$C def_flat --scene flat-road
$C def_flat_again --scene flat-road
$C def_obst4 --scene obstacle --legs strain --t-end 4
$C def_earth --scene flat-road --legs strain --conditions earth --gait $P --t-end 1.5
$C rod32_earth --scene flat-road --legs rod --links 32 --macro-steps 1 --dt 0.00025 --conditions earth --gait $P --t-end 1.5
$C half_flat --scene flat-road --step-tol 1.25e-4
$C half_obst4 --scene obstacle --legs strain --step-tol 1.25e-4 --t-end 4
$C half_paper --scene flat-road --legs strain --gait $P --conditions paper --t-end 9 --step-tol 1.25e-4
$C grid45_paper --scene flat-road --legs strain --gait $P --conditions paper --t-end 9 --strain-step adaptive --dt 0.0045
$C grid55_paper --scene flat-road --legs strain --gait $P --conditions paper --t-end 9 --strain-step adaptive --dt 0.0055
# the paper table's reference at half its step (does the default's 3.35 mm hold against it?)
$C rod32_paper_0125 --scene flat-road --legs rod --links 32 --macro-steps 1 --dt 0.000125 --gait $P --conditions paper --t-end 9
