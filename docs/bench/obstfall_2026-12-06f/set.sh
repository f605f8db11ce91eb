#!/bin/sh
# usage: set.sh CAND MODE RUN...: runs of issue 33's robustness set on the candidate table
# CAND.csv of this folder (designed from CAND.gait when absent) (CAND "k3": the shipped gaits/obstacle.csv), one after the other,
# nice 5, resumable (a run whose CAND_RUN_MODE.txt exists here is skipped).
# MODE open: `crawlsim run` to 35 s scored by table3.py (the h5 in /work/rom_data/obstfall);
# MODE gate: docs/bench/obst_2026-12-06e/gate2.py (the design-referenced gate, PTOL 0.005 MPa)
# to T_GATE s (default 36), its files moved here. Each run adds a line to set.txt.
cd "$(dirname "$0")/../../.."
B=docs/bench/obstfall_2026-12-06f
E=docs/bench/obst_2026-12-06e
O=/work/rom_data/obstfall
. docs/bench/obstacle_pace_2026-12-06/opts.sh
c=$1; mode=$2; shift 2
g=$B/$c; [ "$c" = k3 ] && g=gaits/obstacle
export CRAWLSIM_LIBRARY=${CRAWLSIM_LIBRARY:-$PWD/build/core/libcrawlsim.so}
[ "$c.$mode" = k3.gate ] && { echo "set.sh: k3 gated: docs/bench/obst_2026-12-06e has it" >&2; exit 2; }
mkdir -p $O runs
# CAND.csv is not kept: designed from CAND.gait as gaits/obstacle.csv is (about 15 s)
[ -s $g.csv ] || build/tools/crawlsim gait design $g.gait --stretch --out $g.csv \
  --calibration robot/calibration_fe_leg_modes_sym.h5 --cal-rule rbf-pair --p-max 0.4 > /dev/null || exit 1
for n in "$@"; do
  f=$B/${c}_${n}_$mode
  [ -s $f.txt ] && continue
  if [ $mode = open ]; then
    /usr/bin/time -f "%U s user, %e s wall" nice -n 5 build/tools/crawlsim run --scene obstacle \
      --gait $g.csv --conditions paper $(opt $n) --t-end 35 --out $O/${c}_$n.h5 > $f.log 2>&1
    /usr/bin/python3 docs/bench/obstacle_road_2026-12-05/table3.py $O/${c}_$n.h5 > $f.txt 2>&1
  else
    tag=; [ "$c" = k3 ] || tag=_$c
    GATE_GAIT=$g /usr/bin/time -f "%U s user, %e s wall" nice -n 5 /usr/bin/python3 $E/gate2.py \
      $n ${T_GATE:-36} > $f.log 2>&1
    mv $E/${n}_gate2$tag.txt $f.txt
  fi
  echo "$c $mode $n: $(sed -n 2,3p $f.txt | tr -s ' \n' ' ') | $(tail -n 1 $f.log)" >> $B/set.txt
done
