#!/bin/sh
# noise.sh ORDER:TOL...: the noise floor of the paper's table (`paper`, 9 s) under the adaptive
# step of formula ORDER at TOL: the longest step (--dt, the output's grid) ~10 % shorter and
# longer, 1/220 s and 1/180 s against 5 ms (steps that divide a second, so that the whole
# seconds are samples: output every two steps). Tags n{PREFIX}_{TOL}_{220,180}, PREFIX ORDER
# unless set (lin with CRAWLSIM=/tmp/bdf13/crawlsim_lin, as sweep.sh). From the worktree;
# resumable.
C=$(dirname "$0")/crun.sh
P=gaits/flat_road_paper.csv
for s in "$@"; do
  O=${s%%:*}; T=${s#*:}; X=${PREFIX:-$O}
  for n in 220 180; do
    dt=$(/usr/bin/python3 -c "print(repr(1/$n))"); od=$(/usr/bin/python3 -c "print(repr(2/$n))")
    $C n${X}_${T}_$n --scene flat-road --legs strain --strain-step adaptive --step-order $O \
      --step-tol $T --dt $dt --output-dt $od --gait $P --conditions paper --t-end 9
  done
done
