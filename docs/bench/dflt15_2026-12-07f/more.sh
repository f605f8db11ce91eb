#!/bin/sh
# more.sh: two checks of events.txt's reading, two runs at a time. Slot 1: the nodal rod at 32
# elements, 0.25 ms, the obstacle's whole climb (rod32_climb: no --t-end, the gated run ends
# with its table): does the converged rod climb with this gait past its 9-10 s slide. Slot 2:
# backward Euler's order in the tolerance on the obstacle to 8 s (be_{TOL}_o8 at 5e-4 and
# 6.25e-5 mm, beside the batch's 2.5e-4 and 1.25e-4): the Richardson limit's assumption
# (global error ~ tol^(1/2)). Logs logs/TAG.log, run files $D/TAG.h5; resumable.
H=$(dirname "$0"); D=${D:-/tmp/dflt15/runs}; C=${CRAWLSIM:-/tmp/dflt15/crawlsim}
. "$H/one.sh"
one rod32_climb --scene obstacle --legs rod --links 32 --macro-steps 1 --dt 0.00025 &
{ for tol in 5e-4 6.25e-5; do
    one be_${tol}_o8 --scene obstacle --strain-step adaptive --step-tol $tol --t-end 8
  done; } &
wait
