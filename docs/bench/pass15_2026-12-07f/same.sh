#!/bin/sh
# same.sh SIDE CRAWLSIM: the paper's table (9 s) and `earth` with it (1.5 s) with a crawlsim;
# SIDE base (the branch, tree_skip 0 = main bit for bit) or skip (a scratch build whose default
# is tree_skip 0.1: skipdef_src). Logs and files in /tmp/pass15/same/
cd /work/wt-pass15
side=$1; C=$2; D=/tmp/pass15/same; mkdir -p $D
P=gaits/flat_road_paper.csv
for t in paper earth; do
  if [ $t = paper ]; then a="--scene flat-road --legs strain --gait $P --conditions paper --t-end 9"
  else a="--scene flat-road --legs strain --conditions earth --gait $P --t-end 1.5"; fi
  { uptime; echo "$C run $a --quiet --out $D/${side}_$t.h5"; /usr/bin/time -f "cpu %U s" nice -n 5 $C run $a --quiet --out $D/${side}_$t.h5; echo "rc $?"; uptime; } > $D/${side}_$t.log 2>&1
done
