#!/bin/sh
# ab_cpu.sh N OUT A_BIN B_BIN [ARGS...]: `crawlsim run --scene flat-road ARGS --quiet` with
# binaries A and B alternating, N times each (A B A B ...), nice 5; per run one line
# "A|B user_s load1" appended to OUT. The two see the same load within each pair: compare
# ratios of pairs, not seconds. From the worktree.
N=$1; OUT=$2; A=$3; B=$4; shift 4
# AB_TMP: the runs' scratch directory (default /tmp/speed10); CRAWLSIM_DATA_DIR (default the
# worktree) the data both binaries read, for copies built in a worktree since removed (speed11)
T=${AB_TMP:-/tmp/speed10}
export CRAWLSIM_DATA_DIR=${CRAWLSIM_DATA_DIR:-$(pwd)}
i=0
while [ $i -lt "$N" ]; do
  for w in A B; do
    eval bin=\$$w
    ld=$(cut -d' ' -f1 /proc/loadavg)
    /usr/bin/time -o $T/ab_time -f "%U" nice -n 5 "$bin" run --scene flat-road "$@" \
      --quiet --out $T/ab_$w.h5 > /dev/null 2>&1
    t=$(tail -1 $T/ab_time)
    echo "$w $t $ld" >> "$OUT"
  done
  i=$((i + 1))
done
