#!/bin/sh
# queue.sh: the order the study's runs were made in after runs.sh's first five (killed there;
# the machine's load made the order matter): each skipped when done (crun.sh). From the
# worktree; WAIT=PID first waits for a run in progress.
H=$(dirname "$0")
C=$H/crun.sh
if [ -n "$WAIT" ]; then while kill -0 "$WAIT" 2>/dev/null; do sleep 5; done; fi
A="--legs strain --strain-step adaptive"
O="--scene obstacle --t-end 8"
F="--scene flat-road"
for t in 5e-4 2.5e-4 1e-3; do $C flat_a$t $F $A --step-tol $t; done
$C obst_rod32 $O --legs rod --links 32 --macro-steps 1 --dt 0.00025 \
  --checkpoint /work/rom_data/strdef/obst_rod32.ckpt --checkpoint-every 1
$C obst_a1.25e-4 $O $A --step-tol 1.25e-4
$C flat_a1.25e-4 $F $A --step-tol 1.25e-4
for t in 5e-4 2.5e-4; do
  $C obst_a${t}_H220 $O $A --step-tol $t --dt 0.004545454545454545 --output-dt 0.05
  $C obst_a${t}_H180 $O $A --step-tol $t --dt 0.005555555555555556 --output-dt 0.05
  $C flat_a${t}_H220 $F $A --step-tol $t --dt 0.004545454545454545 --output-dt 0.05
  $C flat_a${t}_H180 $F $A --step-tol $t --dt 0.005555555555555556 --output-dt 0.05
done
$C flat_f0.5ms $F --legs strain --strain-step fixed --dt 0.0005
$C flat_a2e-4 $F $A --step-tol 2e-4
$C obst_a1e-4 $O $A --step-tol 1e-4
$C flat_a1e-4 $F $A --step-tol 1e-4
$C obst_f0.25ms $O --legs strain --strain-step fixed --dt 0.00025
$C flat_f0.25ms $F --legs strain --strain-step fixed --dt 0.00025
