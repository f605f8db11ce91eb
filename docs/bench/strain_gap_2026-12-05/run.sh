#!/bin/sh
# Issue 32, why the strain leg's flat road differs from the 16-element nodal rod
# (docs/notes/strain_leg.md "Why the flat road differs"), from the repository root; outputs in
# build/sg (resumable: a finished run is kept). Usage: sh run.sh NAME ARGS...
B=${B:-build/tools/crawlsim}
O=build/sg
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
