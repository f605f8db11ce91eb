#!/bin/sh
# queue2.sh: the study's second queue (after queue.sh's rod reference; the load, 8-12 on the 2
# cores, left time for fewer runs than queue.sh lists): the obstacle's half-tolerance partner
# of 2.5e-4, the longest step ±10 % (the step half of the noise floor), the Magnus
# sub-intervals 2 (CRAWLSIM_NEW: the build with --strain-sub, default 2) at the two candidate
# tolerances, the pneumatic half of the noise floor (noise.sh), then what queue.sh had left.
# From the worktree; WAIT=PID first waits for a run in progress.
H=$(dirname "$0")
C=$H/crun.sh
N=/work/rom_data/strdef/crawlsim_new
if [ -n "$WAIT" ]; then while kill -0 "$WAIT" 2>/dev/null; do sleep 5; done; fi
A="--legs strain --strain-step adaptive"
O="--scene obstacle --t-end 8"
F="--scene flat-road"
$C obst_a1.25e-4 $O $A --step-tol 1.25e-4
for t in 5e-4 2.5e-4; do
  $C obst_a${t}_H220 $O $A --step-tol $t --dt 0.004545454545454545 --output-dt 0.05
  $C obst_a${t}_H180 $O $A --step-tol $t --dt 0.005555555555555556 --output-dt 0.05
done
for t in 5e-4 2.5e-4; do
  CRAWLSIM=$N $C obst_a${t}_sub2 $O $A --step-tol $t --strain-sub 2
  CRAWLSIM=$N $C flat_a${t}_sub2 $F $A --step-tol $t --strain-sub 2
done
# the new build at sub 4 against the study's binary (the same run, bit for bit)
CRAWLSIM=$N $C obst_a5e-4_sub4new $O --legs strain --step-tol 5e-4 --strain-sub 4
$H/noise.sh 5e-4
for t in 5e-4 2.5e-4; do
  $C flat_a${t}_H220 $F $A --step-tol $t --dt 0.004545454545454545 --output-dt 0.05
  $C flat_a${t}_H180 $F $A --step-tol $t --dt 0.005555555555555556 --output-dt 0.05
done
$C flat_a1.25e-4 $F $A --step-tol 1.25e-4
$C obst_f0.25ms $O --legs strain --strain-step fixed --dt 0.00025
$C flat_f0.5ms $F --legs strain --strain-step fixed --dt 0.0005
