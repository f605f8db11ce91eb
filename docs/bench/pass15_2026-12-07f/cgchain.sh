#!/bin/bash
cd /work/wt-pass15
export CG_OUT=/tmp/pass15/cg
CS_BENCH_SKIP=0 docs/bench/speed_2026-12-07/cg.sh /tmp/pass15/bin1/bench_strain_driver base.flat 1 1 strain:2 2.5e-4 1
CS_BENCH_SKIP=0.1 docs/bench/speed_2026-12-07/cg.sh /tmp/pass15/bin1/bench_strain_driver skip.flat 1 1 strain:2 2.5e-4 1
echo chain done
