#!/bin/sh
# runs.sh WHO [long|earth]: crawlsim /tmp/legpass19/bin/crawlsim_WHO with the default legs
# (strain, backward Euler, adaptive 2.5e-4 mm): the flat road and the obstacle for 2 s
# (WHO.o1.SCENE), with `long` the flat road's whole gait (9.5 s) and the obstacle's first 4 s
# (WHO.long.SCENE), with `earth` the paper's gait under `earth` for 1.5 s (it falls; the log
# gives the time). h5 and logs in /tmp/legpass19/runs; a run whose h5 exists is skipped
B=/tmp/legpass19/bin/crawlsim_$1 R=/tmp/legpass19/runs/$1
cd "$(dirname "$0")/../../.." && mkdir -p /tmp/legpass19/runs || exit 1
go() { # NAME CRAWLSIM-ARGS...
  n=$1; shift
  if [ ! -f $R.$n.h5 ]; then
    { uptime; /usr/bin/time -f "cpu %U s" nice -n 5 $B run --legs strain "$@" --out $R.$n.h5.tmp
      uptime; } > $R.$n.log 2>&1 && mv $R.$n.h5.tmp $R.$n.h5
  fi
}
case "$2" in
  long) go long.flat-road --scene flat-road; go long.obstacle --scene obstacle --t-end 4 ;;
  earth) go earth.flat-road --scene flat-road --gait gaits/flat_road_paper.csv \
           --conditions earth --t-end 1.5 ;;
  *) go o1.flat-road --scene flat-road --t-end 2; go o1.obstacle --scene obstacle --t-end 2 ;;
esac
