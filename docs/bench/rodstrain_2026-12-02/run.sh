#!/bin/bash
cd /work/wt-strain/build/tests/core
B=./bench_flatroad
echo "start $(date -u +%H:%M:%S)"
CS_BENCH_KEEP=/tmp/sbench/nodal.h5 $B rod 4 1e-3 9 > /tmp/sbench/nodal.txt 2>&1
echo "nodal done $(date -u +%H:%M:%S)"
CS_BENCH_KEEP=/tmp/sbench/s0.h5 $B strain 4 1e-3 9 - - 1 1 1 nan 0 0 > /tmp/sbench/s0.txt 2>&1
echo "s0 done $(date -u +%H:%M:%S)"
CS_BENCH_KEEP=/tmp/sbench/s0ns.h5 $B strain 4 1e-3 9 - - 1 1 1 nan 0 1 > /tmp/sbench/s0ns.txt 2>&1
echo "s0ns done $(date -u +%H:%M:%S)"
CS_BENCH_KEEP=/tmp/sbench/s1.h5 $B strain 4 1e-3 9 - - 1 1 1 nan 1 0 > /tmp/sbench/s1.txt 2>&1
echo "s1 done $(date -u +%H:%M:%S)"
