#!/bin/sh
# sweep.sh ORDER TOL...: the adaptive tree step of formula ORDER (1 backward Euler, 2 BDF2) at
# each local error TOL (mm) on every run the rules of issues 32/33 touch: the flat road's
# designed gait (scene defaults, 9.5 s), the paper's table (`paper`, 9 s), `earth` with the
# paper's table (1.5 s), the obstacle's first 4 s. Tags: {PREFIX}_{TOL}_{flat,paper,earth,obst4},
# PREFIX o{ORDER} unless set (lin: the linearly implicit BDF2's scratch build, with
# CRAWLSIM=/tmp/bdf13/crawlsim_lin); DT set: the longest step --dt DT (and the output every
# 10 ms, a multiple of it), tags {PREFIX}dt{DT}_... From the worktree; resumable.
C=$(dirname "$0")/crun.sh
P=gaits/flat_road_paper.csv
O=$1; shift
X=${PREFIX:-o$O}
[ -n "$DT" ] && X=${X}dt$DT && XA="--dt $DT --output-dt 0.01"
for T in "$@"; do
  A="--legs strain --strain-step adaptive --step-order $O --step-tol $T $XA"
  $C ${X}_${T}_flat --scene flat-road $A
  $C ${X}_${T}_paper --scene flat-road $A --gait $P --conditions paper --t-end 9
  $C ${X}_${T}_earth --scene flat-road $A --conditions earth --gait $P --t-end 1.5
  $C ${X}_${T}_obst4 --scene obstacle $A --t-end 4
done
