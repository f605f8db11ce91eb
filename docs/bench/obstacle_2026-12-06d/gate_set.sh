#!/bin/sh
# usage: gate_set.sh T_END RUN...: gate.py's runs one after the other (resumable: a run with its
# RUN_gate.txt here is skipped), nice 5; CRAWLSIM_LIBRARY: the library (default build/core's)
cd "$(dirname "$0")/../../.."
B=docs/bench/obstacle_2026-12-06d
T=$1; shift
export CRAWLSIM_LIBRARY=${CRAWLSIM_LIBRARY:-$PWD/build/core/libcrawlsim.so}
for n in "$@"; do
  tag=; [ -n "$GATE_GAIT" ] && tag=_$(basename $GATE_GAIT); [ -n "$GATE_SENSOR" ] && [ "$GATE_SENSOR" != feet ] && tag=${tag}_$GATE_SENSOR
  [ -s $B/${n}_gate$tag.txt ] && continue
  /usr/bin/time -f "%U s user, %e s wall" nice -n 5 /usr/bin/python3 $B/gate.py $n $T > $B/${n}_gate$tag.log 2>&1
done
