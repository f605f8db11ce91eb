#!/bin/bash
# runs.sh: the branch's build with scratch.patch (CR18_PASSES / CR18_CARRY in cs_defaultOptions:
# crawlsim has no switch for tree_carry). Files in R, logs in logs/.
#   def2: the default, flat road 2 s, crawlsim, against main 78c770c built in /tmp/carry18/main
#         (git archive; /work/main/build is older than main) (bit for bit)
#   bench: one pass + carry (the exact linear-model contact force), flat road 9.5 s and the
#          obstacle's first 4 s (bench_strain_driver, as event17's branch.sh)
#   paper: the paper's table 9 s, earth 1.5 s (crawlsim, as event17's carry.sh)
W=${W:-/work/wt-carry18}; R=${R:-/tmp/carry18/runs}; L=$(cd $(dirname "$0") && pwd)/logs
mkdir -p $R $L; export CS_SOURCE_DIR=$W; cd $W
C=$W/build/tools/crawlsim; B=$W/build/tests/core/bench_strain_driver
P=$W/gaits/flat_road_paper.csv
crun() { local tag=$1 bin=$2; shift 2
  { uptime; echo "$tag: $bin run $* --quiet --out $R/$tag.h5"
    /usr/bin/time -f "%U user %S sys %e wall" nice -n 5 env "${ENVS[@]}" $bin run "$@" --quiet --out $R/$tag.h5
    echo "rc $?"; uptime; } > $L/$tag.log 2>&1; echo "$tag $(grep '^rc ' $L/$tag.log)"; }
case $1 in
def2)
  ENVS=(X=0); crun def2_main /tmp/carry18/main/build/tools/crawlsim --scene flat-road --legs strain --t-end 2 &
  ENVS=(X=0); crun def2_branch $C --scene flat-road --legs strain --t-end 2; wait ;;
bench)
  d=$R/c18; mkdir -p $d
  { uptime; CS_BENCH_KEEP=$d CS_BENCH_PASSES=1 CS_BENCH_CARRY=1 CS_BENCH_ADAPTIVE=2.5e-4 nice -n 5 $B 9.5 strain:2; uptime; } > $L/bench_flat.log 2>&1 &
  { uptime; CS_BENCH_SCENE=obstacle CS_BENCH_KEEP=$d CS_BENCH_PASSES=1 CS_BENCH_CARRY=1 CS_BENCH_ADAPTIVE=2.5e-4 nice -n 5 $B 4 strain:2; uptime; } > $L/bench_obst.log 2>&1
  wait ;;
paper)
  ENVS=(CR18_PASSES=1 CR18_CARRY=1); crun c18_paper $C --scene flat-road --legs strain --gait $P --conditions paper --t-end 9 ;;
earth)
  ENVS=(CR18_PASSES=1 CR18_CARRY=1); crun c18_earth $C --scene flat-road --legs strain --conditions earth --gait $P --t-end 1.5 ;;
esac
# old: the first form (the ghosts at the end) in the same build: scratch CR18_OLD=1 read in
# robot_strain_carry.c (a scratch edit, not committed; scratch.patch)
case $1 in
old)
  ENVS=(CR18_PASSES=1 CR18_CARRY=1 CR18_OLD=1); crun old_paper $C --scene flat-road --legs strain --gait $P --conditions paper --t-end 9 ;;
esac
case $1 in
climb)
  ENVS=(CR18_PASSES=1 CR18_CARRY=1); crun c18_obst $C --scene obstacle --legs strain ;;
esac
case $1 in
rod125)  # the reference at half the step: the rod at 32 elements, 0.125 ms, the paper's table
  ENVS=(X=0); crun rod32_125_paper $C --scene flat-road --legs rod --links 32 --macro-steps 1 --dt 0.000125 --gait $P --conditions paper --t-end 9 ;;
esac
