#!/bin/sh
# queue3.sh: the new defaults as a user runs them (`--legs strain`, no other step flag;
# CRAWLSIM = crawlsim_def, this branch's build with the adaptive 2.5e-4 mm and sub 2 defaults):
# `earth` with the paper's table (the fall's time against the rod's 1.023 s), the whole obstacle
# climb (its end against Table 3), the paper's table (paper, 9 s). From the worktree; WAIT=PID
# first waits for a run in progress.
H=$(dirname "$0")
C=$H/crun.sh
export CRAWLSIM=/work/rom_data/strdef/crawlsim_def
if [ -n "$WAIT" ]; then while kill -0 "$WAIT" 2>/dev/null; do sleep 5; done; fi
$C def_earth --scene flat-road --legs strain --conditions earth --gait gaits/flat_road_paper.csv --t-end 1.5
$C def_obst --scene obstacle --legs strain
$C def_paper --scene flat-road --legs strain --gait gaits/flat_road_paper.csv --conditions paper --t-end 9
