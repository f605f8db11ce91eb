#!/bin/bash
# runs.sh CASE: crawlsim runs of a scratch build (onepass_bdf2.patch applied: RS19_PASSES /
# RS19_CARRY in cs_defaultOptions, RS19_FULL the full assembly at BDF2's first iterate) in C.
# Every run: BDF2 adaptive (--strain-step adaptive --step-order 2), files in $R, logs in logs/.
#   paper TAG TOL [DT]: the paper's table 9 s;  earth TAG TOL [DT]: `earth` with the paper's
#   table 1.5 s;  flat TAG TOL [DT]: the flat road 9.5 s;  obst TAG TOL [DT]: the obstacle's 4 s;
#   climb TAG TOL: the whole obstacle climb.  ENVS (e.g. "RS19_PASSES=1 RS19_FULL=1") in the env.
W=${W:-/work/wt-rosen19}; R=${R:-/tmp/rosen19/runs}; L=$(cd $(dirname "$0") && pwd)/logs
C=${C:-/tmp/rosen19/b2/tools/crawlsim}; P=$W/gaits/flat_road_paper.csv
export CS_SOURCE_DIR=$W; cd $W; mkdir -p $R $L
case_=$1; tag=$2; tol=$3; dt=${4:-0.005}
A=(--legs strain --strain-step adaptive --step-order 2 --step-tol $tol --dt $dt)
case $case_ in
paper) S=(--scene flat-road --gait $P --conditions paper --t-end 9) ;;
earth) S=(--scene flat-road --gait $P --conditions earth --t-end 1.5) ;;
flat)  S=(--scene flat-road --t-end 9.5) ;;
obst)  S=(--scene obstacle --t-end 4) ;;
climb) S=(--scene obstacle) ;;
esac
{ uptime; echo "$tag: ${ENVS:-} crawlsim run ${S[*]} ${A[*]} --quiet --out $R/$tag.h5"
  /usr/bin/time -f "%U user %S sys %e wall" nice -n 5 env ${ENVS:-X=0} $C run "${S[@]}" "${A[@]}" --quiet --out $R/$tag.h5
  echo "rc $?"; uptime; } > $L/$tag.log 2>&1
echo "$tag $(grep '^rc ' $L/$tag.log)"
