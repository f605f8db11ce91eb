#!/bin/sh
# usage: trial.sh GAIT_NAME T_END RUN... : runs/GAIT_NAME.csv with its footholds
# (runs/GAIT_NAME.foothold, gen.sh) on the obstacle scene with each robustness option in turn
# (docs/bench/obstacle_pace_2026-12-06/opts.sh), to T_END, one after the other (nice 10;
# CRAWLSIM: the binary); FH=none runs the table alone; a run whose score file exists is
# skipped (resumable); logs and Table 3 scores here, one line per run in trials.txt (with the
# footholds' choices)
cd "$(dirname "$0")/../../.."
B=docs/bench/obstacle_foothold_2026-12-06
g=$1; te=$2; shift 2
fh=${FH:-runs/$g.foothold}
tag=$g; [ "$fh" = none ] && tag=${g}_nofh
. docs/bench/obstacle_pace_2026-12-06/opts.sh
for n in "$@"; do
  [ -s $B/${tag}_$n.table3.txt ] && continue
  nice -n 10 ${CRAWLSIM:-build/tools/crawlsim} run --scene obstacle --gait runs/$g.csv --foothold $fh --conditions paper --calibration robot/calibration_fe_leg_modes_sym.h5 --cal-rule rbf-pair $(opt $n) --t-end $te --out runs/${tag}_$n.h5 > $B/${tag}_$n.log 2>&1
  /usr/bin/python3 docs/bench/obstacle_road_2026-12-05/table3.py runs/${tag}_$n.h5 > $B/${tag}_$n.table3.txt 2>&1
  ch=$(/usr/bin/python3 -c "import h5py,sys; f=h5py.File(sys.argv[1],'r'); print(f.attrs.get('foothold_choices', b'').decode() if isinstance(f.attrs.get('foothold_choices', ''), bytes) else f.attrs.get('foothold_choices', ''))" runs/${tag}_$n.h5 2>/dev/null)
  echo "${tag} $n $(opt $n): $(sed -n 2p $B/${tag}_$n.table3.txt) | $(tail -n 1 $B/${tag}_$n.table3.txt) | footholds: $ch" >> $B/trials.txt
done
