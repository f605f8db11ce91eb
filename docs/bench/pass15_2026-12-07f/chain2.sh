#!/bin/bash
# chain2: HEAD's bench (the scratch trace build, trace off) and bin2 (tree_skip with the landing catch)
cd /work/wt-pass15/build/tests/core
export CS_SOURCE_DIR=/work/wt-pass15
run() { # BIN DIR SKIP
  mkdir -p $2; uptime
  CS_BENCH_KEEP=$2 CS_BENCH_SKIP=$3 CS_BENCH_ADAPTIVE=2.5e-4 nice -n 5 $1 9.5 strain:2 2>&1 | grep -E "x\(end\)|tree:|window"
  CS_BENCH_SCENE=obstacle CS_BENCH_KEEP=$2 CS_BENCH_SKIP=$3 CS_BENCH_ADAPTIVE=2.5e-4 nice -n 5 $1 4 strain:2 2>&1 | grep -E "x\(end\)|tree:|window"
}
run /tmp/pass15/trace_build/tests/core/bench_strain_driver /tmp/pass15/runs/head 0
run /tmp/pass15/bin2/bench_strain_driver /tmp/pass15/runs/b2skip0 0
run /tmp/pass15/bin2/bench_strain_driver /tmp/pass15/runs/b2skip0.1 0.1
uptime
cd /work/wt-pass15
export CG_OUT=/tmp/pass15/cg
CS_BENCH_SKIP=0.1 docs/bench/speed_2026-12-07/cg.sh /tmp/pass15/bin2/bench_strain_driver skip2.flat 1 1 strain:2 2.5e-4 1
echo chain2 done
