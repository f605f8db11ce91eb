#!/bin/sh
# run_bare.sh: the bare linearised pass (tree_iterations 1: no test, no second pass) on the 9 s
# flat road at 5, 2.5 and 1 ms; from build/tests/core, CS_BENCH_KEEP another directory than
# run_steps.sh's (the file names are the same)
uptime
CS_BENCH_PASSES=1 nice -n 5 ./bench_strain_driver 9 strain:3:0.005:1 strain:3:0.0025:1 strain:3:0.001:1
uptime
