#!/bin/sh
# runs2.sh: after runs.sh, the tolerances below 2.5e-4 (the half-tolerance partners of 2.5e-4
# and 2e-4) and the noise floor of the adaptive step: its longest step (the grid) ±10 %
# (1/220 s and 1/180 s, output every 0.05 s, a multiple of both, so the whole seconds are
# samples); the pneumatic tolerance 10x tighter is bench_strain_driver's (noise.sh).
H=$(dirname "$0")
C=$H/crun.sh
A="--legs strain --strain-step adaptive"
O="--scene obstacle --t-end 8"
F="--scene flat-road"
for t in 1.25e-4 1e-4; do $C obst_a$t $O $A --step-tol $t; done
for t in 1.25e-4 1e-4; do $C flat_a$t $F $A --step-tol $t; done
for t in 5e-4 2.5e-4; do
  $C obst_a${t}_H220 $O $A --step-tol $t --dt 0.004545454545454545 --output-dt 0.05
  $C obst_a${t}_H180 $O $A --step-tol $t --dt 0.005555555555555556 --output-dt 0.05
  $C flat_a${t}_H220 $F $A --step-tol $t --dt 0.004545454545454545 --output-dt 0.05
  $C flat_a${t}_H180 $F $A --step-tol $t --dt 0.005555555555555556 --output-dt 0.05
done
