#!/bin/sh
# usage: set.sh GAIT_NAME RUN...: issue 33's robustness set, one run after the other (nice 5):
# runs/GAIT_NAME.csv with its footholds (runs/GAIT_NAME.foothold, gen.sh; FH=none: the table
# alone) on the obstacle scene to 35 s, plus each run's option
# (docs/bench/obstacle_pace_2026-12-06/opts.sh; RUN nominal ramp0.1 ramp0.5 mu0.6 mu1.0 m25g
# m75g tau0.5x tau2x dt_half). Resumable: a run whose score exists is skipped. Logs and Table 3
# scores (docs/bench/obstacle_road_2026-12-05/table3.py) here, one line per run in set.txt with
# the footholds' choices; run files in runs/ (not kept).
cd "$(dirname "$0")/../../.."
B=docs/bench/obstacle_2026-12-06c
g=$1; shift
fh=${FH:-runs/$g.foothold}
tag=$g; [ "$fh" = none ] && tag=${g}_nofh
. docs/bench/obstacle_pace_2026-12-06/opts.sh
for n in "$@"; do
  [ -s $B/${tag}_$n.table3.txt ] && continue
  nice -n 5 ${CRAWLSIM:-build/tools/crawlsim} run --scene obstacle --gait runs/$g.csv --foothold $fh --conditions paper $(opt $n) --t-end 35 --out runs/${tag}_$n.h5 > $B/${tag}_$n.log 2>&1
  /usr/bin/python3 docs/bench/obstacle_road_2026-12-05/table3.py runs/${tag}_$n.h5 > $B/${tag}_$n.table3.txt 2>&1
  ch=$(/usr/bin/python3 -c "import h5py,sys; f=h5py.File(sys.argv[1],'r'); v=f.attrs.get('foothold_choices', ''); print(v.decode() if isinstance(v, bytes) else v)" runs/${tag}_$n.h5 2>/dev/null)
  echo "${tag} $n $(opt $n): $(sed -n 2p $B/${tag}_$n.table3.txt) | $(tail -n 1 $B/${tag}_$n.table3.txt) | footholds: $ch" >> $B/set.txt
done
