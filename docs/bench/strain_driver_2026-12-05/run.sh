#!/bin/sh
# The strain leg through the driver against the nodal rod (docs/notes/strain_leg.md "In the
# driver"), from the repository root; outputs in build/sd (resumable: a finished run is kept).
B=${B:-build/tools/crawlsim}
O=build/sd
mkdir -p $O
run() { # name, args...
  n=$1; shift
  [ -f $O/$n.h5 ] && return
  /usr/bin/time -f "cpu %U s wall %e s" nice -n 10 $B run --quiet --out $O/$n.tmp.h5 "$@" > $O/$n.log 2>&1 &&
    mv $O/$n.tmp.h5 $O/$n.h5
}
case "$1" in
  ref)   run rod16_dt025 --scene flat-road --legs rod --links 16 --dt 0.00025 ;;
  refp)  run rod16_dt025_paper --scene flat-road --gait gaits/flat_road_paper.csv --conditions paper --legs rod --links 16 --dt 0.00025 ;;
  rod8)  run rod8 --scene flat-road ;;
  strain) run strain_dt1 --scene flat-road --legs strain --dt 0.001 ;;
  strainp) run strain_dt1_paper --scene flat-road --gait gaits/flat_road_paper.csv --conditions paper --legs strain --dt 0.001 ;;
  strain05) run strain_dt05 --scene flat-road --legs strain --dt 0.0005 ;;
  strain2) run strain_dt2 --scene flat-road --legs strain --dt 0.002 ;;
  *) run "$@" ;;
esac
# The runs of tracks.txt (sh run.sh NAME ARGS... for the others):
#   ref refp rod8 strain strainp strain05 strain2
#   strain_l4 --scene flat-road --legs strain --links 4 --dt 0.001
#   rod16_dt05 --scene flat-road --legs rod --links 16 --dt 0.0005
#   rod16_dt1 --scene flat-road --legs rod --links 16
#   rod12_dt1 --scene flat-road --legs rod --links 12
#   rod24_dt1 --scene flat-road --legs rod --links 24
#   rod8_dt025 --scene flat-road --legs rod --links 8 --dt 0.00025
#   ob_rod6_dt025 --scene obstacle --legs rod --links 6 --dt 0.00025 --t-end 4
#   ob_strain --scene obstacle --legs strain --dt 0.001 --t-end 4
#   ob_strain_l2 --scene obstacle --legs strain --links 2 --dt 0.001 --t-end 4
#   ob_strain_l4 --scene obstacle --legs strain --links 4 --dt 0.001 --t-end 4
#   earth_strain --scene flat-road --gait gaits/flat_road_paper.csv --conditions earth --legs strain --dt 0.001 --t-end 4
#   earth_rod8 --scene flat-road --gait gaits/flat_road_paper.csv --conditions earth --t-end 4
#   earth_rod16 --scene flat-road --gait gaits/flat_road_paper.csv --conditions earth --legs rod --links 16 --t-end 4
#   ob_strain_dt05 --scene obstacle --legs strain --dt 0.0005 --t-end 4
#   ob_strain_dt025 --scene obstacle --legs strain --dt 0.00025 --t-end 4
#   strain025 --scene flat-road --legs strain --dt 0.00025
# (the strain runs were made when the level's default step was 1 ms; --dt 0.001 says it now)
