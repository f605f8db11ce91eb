#!/bin/sh
# same.sh: the strain kernels at -O3 (this branch's build, copied to /tmp/speed10/crawlsim_new)
# against the base build (-O2, /tmp/speed10/crawlsim_base) on the default's runs: the flat road
# (designed gait), the paper's table, `earth` with it, the obstacle's first 4 s on strain legs,
# a fixed 5 ms run, and the obstacle's own default (rod legs, which use the soft law too); the files compared dataset by dataset (../speed9_2026-12-07b/h5diff.py)
# into same.txt. From the worktree; resumable (crun.sh).
H=$(dirname "$0")
C=$H/../levels9_2026-12-07b/crun.sh
export D=/tmp/speed10/runs CRAWLSIM=/tmp/speed10/crawlsim_base LOGS=$H/logs
P=gaits/flat_road_paper.csv
$C def_obst4 --scene obstacle --legs strain --t-end 4
$C def_obst4_rod --scene obstacle --t-end 4
export CRAWLSIM=/tmp/speed10/crawlsim_new
$C new_flat --scene flat-road
$C new_paper --scene flat-road --legs strain --gait $P --conditions paper --t-end 9
$C new_earth --scene flat-road --legs strain --conditions earth --gait $P --t-end 1.5
$C new_obst4 --scene obstacle --legs strain --t-end 4
$C new_f5_flat --scene flat-road --legs strain --dt 0.005
$C new_obst4_rod --scene obstacle --t-end 4
: > $H/same.txt
for p in "def_flat new_flat" "def_paper new_paper" "def_earth new_earth" "def_obst4 new_obst4" \
         "f0.005_flat new_f5_flat" "def_obst4_rod new_obst4_rod"; do
  set -- $p
  echo "$1 (-O2) vs $2 (-O3): $(/usr/bin/python3 $H/../speed9_2026-12-07b/h5diff.py /tmp/speed10/runs/$1.h5 /tmp/speed10/runs/$2.h5 | tr '\n' ' ')" >> $H/same.txt
done
