#!/bin/sh
# usage: gate2_set.sh T_END RUN...: gate2.py's runs one after the other, nice 5, resumable (a run
# whose RUN_gate2.txt exists here is skipped); CRAWLSIM_LIBRARY: the library (default build/core's);
# PTOL=MPa: the gate's tolerance (default gate2.py's 0.005; files RUN_gate2_pPTOL.*); GATE_EVERY=1:
# every chamber gates (RUN_gate2_every.*); GATE_GAIT=NAME: NAME.csv, NAME.gait (RUN_gate2_BASENAME.*)
cd "$(dirname "$0")/../../.."
B=docs/bench/obst_2026-12-06e
T=$1; shift
export CRAWLSIM_LIBRARY=${CRAWLSIM_LIBRARY:-$PWD/build/core/libcrawlsim.so}
for n in "$@"; do
  tag=; [ -n "$PTOL" ] && tag=_p$PTOL; [ "$GATE_EVERY" = 1 ] && tag=${tag}_every; [ -n "$GATE_GAIT" ] && tag=${tag}_$(basename $GATE_GAIT)
  [ -s $B/${n}_gate2$tag.txt ] && continue
  /usr/bin/time -f "%U s user, %e s wall" nice -n 5 /usr/bin/python3 $B/gate2.py $n $T $PTOL > $B/${n}_gate2$tag.log 2>&1
done
