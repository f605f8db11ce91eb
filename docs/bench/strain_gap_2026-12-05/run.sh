#!/bin/sh
# Issue 32, why the strain leg's flat road differs from the 16-element nodal rod
# (docs/notes/strain_leg.md "Why the flat road differs"), from the repository root; outputs in
# build/sg (resumable: a finished run is kept). Usage: sh run.sh NAME ARGS...
B=${B:-build/tools/crawlsim}
O=${O:-build/sg}
mkdir -p $O
n=$1; shift
[ -f $O/$n.h5 ] && exit 0
/usr/bin/time -f "cpu %U s wall %e s" nice -n 10 $B run --quiet --out $O/$n.tmp.h5 "$@" > $O/$n.log 2>&1
rc=$?
mv $O/$n.tmp.h5 $O/$n.h5
echo "exit $rc" >> $O/$n.log
# The runs (all --scene flat-road, its defaults otherwise; the output every 0.01 s):
#   rod16_dt025 --legs rod --links 16 --dt 0.00025
#   rod8 --legs rod --links 8            rod12 --legs rod --links 12
#   rod24 --legs rod --links 24          strain1 --legs strain --dt 0.001
#   rod24_dt025 --legs rod --links 24 --dt 0.00025
#   rod24_tol01 --legs rod --links 24 --rod-tol 0.1
# Before the rod's capsule fix (commit 2d86aff): O=build/sg, out/*.log, compare_before.txt,
# tracks_before.txt; rod24_dt025 and rod24_tol01 with --t-end 3, rod24 fell at 1.739 s.
# After it: O=build/sg2 sh run.sh NAME ... for rod16_dt025 rod16 (--links 16) rod12 rod8 rod24
# and rod6_dt025 (--links 6 --dt 0.00025); out/fixed_*.log, compare_fixed.txt, tracks_fixed.txt.
# One leg: build/tests/robot/bench_leg_pair swing|side|push 12.5 5 T rod:16 rod:8 strain:3 with
# CS_SOURCE_DIR=$PWD CS_CALIBRATION=robot/calibration_fe_leg_modes_sym.h5 (out/pair_*.txt).
# Also after it: rod4 (--links 4), rod16_dt025_paper / rod8_paper / strain_paper (--gait
# gaits/flat_road_paper.csv --conditions paper; strain --dt 0.001), ob_rod6_dt025 (--scene
# obstacle --links 6 --dt 0.00025 --t-end 4); compare_fixed_paper.txt.
