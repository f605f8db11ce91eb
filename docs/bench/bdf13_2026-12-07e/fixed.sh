#!/bin/sh
# fixed.sh: BDF2 at a fixed 5 ms step on the flat road's designed gait, the full Newton
# (step_refresh 1, this branch's build: tag f5_o2_flat) and the linearly implicit one
# (step_refresh 0, /tmp/bdf13/crawlsim_lin: tag f5_lin_flat): does the old defect of the
# linearly implicit BDF2 through the driver (24.7 mm off the rod at fixed 5 ms, branch fast,
# docs/notes/strain_leg.md "The linearly implicit BDF2") still stand? From the worktree;
# resumable.
C=$(dirname "$0")/crun.sh
A="--scene flat-road --legs strain --step-order 2 --dt 0.005"
$C f5_o2_flat $A
CRAWLSIM=/tmp/bdf13/crawlsim_lin $C f5_lin_flat $A
# the obstacle's first 4 s the same two ways (robot/levels.csv's fixed BDF2 rows: flat road and
# obstacle at 5 ms, measured with the whole residual)
$C f5_o2_obst4 --scene obstacle --legs strain --step-order 2 --dt 0.005 --t-end 4
CRAWLSIM=/tmp/bdf13/crawlsim_lin $C f5_lin_obst4 --scene obstacle --legs strain --step-order 2 --dt 0.005 --t-end 4
