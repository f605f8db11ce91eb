#!/bin/sh
# runs.sh: every run of this folder's tables, one after the other (the machine's rule: one heavy
# simulation at a time), from the worktree after a build; tracks and logs in $D
# (/work/rom_data/strainacc by default; HDF5 tracks are not committed: this regenerates them,
# ~25 min of CPU on a quiet machine, most of it the rods at 24 and 32 elements per segment).
# The reference tracks of robot/levels.csv (the rod at 16 elements and 0.25 ms, flat road and
# obstacle) come from tools/bench_levels.py (its --work folder; this session read /tmp/lv/work).
set -e
W=$(cd "$(dirname "$0")/../../.." && pwd)
H=$W/docs/bench/strainacc_2026-12-06f
C=$H/crun.sh
B=$H/brun.sh
cd "$W"
# the flat road (designed gait), strain: the step, its +-10 %, the pneumatic tolerance x 0.1, the basis
( cd build/tests/core && export CS_SOURCE_DIR="$W" &&
  $B f_l2_1ms flat-road 9 strain:2:0.001 &&
  $B f_l2_05ms flat-road 9 strain:2:0.0005 &&
  $B f_l2_1ms_ptol flat-road 9 strain:2:0.001 CS_BENCH_PTOL=0.1 &&
  $B f_l2_09ms flat-road 9 strain:2:0.0009 &&
  $B f_l2_11ms flat-road 9 strain:2:0.0011 &&
  $B f_l2_j1 flat-road 9 strain:2:0.001:0:0:-1:-1:-1:-1:1 &&
  $B f_l4 flat-road 9 strain:4:0.001 )
# the nodal rod's convergence in its segments' elements (0.5 ms) and in its joints' elements
for n in 8 12 24 32; do
  $C f_rod${n}_05ms --scene flat-road --legs rod --links $n --dt 0.0005 --t-end 9
done
( cd build/tests/core && export CS_SOURCE_DIR="$W" &&
  $B f_rod16_jl4_05ms flat-road 9 rod:16:0.0005:0:0:-1:-1:-1:-1:4 &&
  $B f_rod16_jl2_05ms flat-road 9 rod:16:0.0005:0:0:-1:-1:-1:-1:2 )
# the obstacle's first 4 s: the step (backward Euler and BDF2), the rod at 24 and 32 elements
( cd build/tests/core && export CS_SOURCE_DIR="$W" &&
  $B o_l2_1ms obstacle 4 strain:2:0.001 &&
  $B o_l2_05ms obstacle 4 strain:2:0.0005 &&
  $B o_l2_1ms_o2 obstacle 4 strain:2:0.001:2 &&
  $B o_l2_05ms_o2 obstacle 4 strain:2:0.0005:2 &&
  $B o_l2_025ms obstacle 4 strain:2:0.00025 &&
  $B o_l2_075ms obstacle 4 strain:2:0.00075 &&
  $B o_l2_0375ms obstacle 4 strain:2:0.000375 &&
  $B o_l2_045ms obstacle 4 strain:2:0.00045 &&
  $B o_l2_055ms obstacle 4 strain:2:0.00055 &&
  $B o_l2_1ms_ptol obstacle 4 strain:2:0.001 CS_BENCH_PTOL=0.1 &&
  $B o_l2_05ms_ptol obstacle 4 strain:2:0.0005 CS_BENCH_PTOL=0.1 )
$C o_rod24_025ms --scene obstacle --legs rod --links 24 --dt 0.00025 --t-end 4
$C o_rod32_025ms --scene obstacle --legs rod --links 32 --dt 0.00025 --t-end 4
# the paper's table under paper: the rod at 16 (0.25 ms) and 32 (0.5 ms), strain at 0.5, 0.9, 1, 1.1 ms
$C p_rod16_025ms --scene flat-road --legs rod --links 16 --dt 0.00025 --gait gaits/flat_road_paper.csv --conditions paper --t-end 9
$C p_rod32_05ms --scene flat-road --legs rod --links 32 --dt 0.0005 --gait gaits/flat_road_paper.csv --conditions paper --t-end 9
for h in 0.0005 0.0009 0.001 0.0011; do
  $C p_strain_$h --scene flat-road --legs strain --dt $h --gait gaits/flat_road_paper.csv --conditions paper --t-end 9
done
# earth with the paper's table at 0.5 ms (the fall)
$C e_strain_05ms --scene flat-road --legs strain --dt 0.0005 --conditions earth --gait gaits/flat_road_paper.csv --t-end 1.5
