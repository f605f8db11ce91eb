#!/bin/sh
# ab_cpu.sh T H: backward Euler converged and one_pass 1 interleaved in one process (A B A B) on
# the flat road's first T s at step H; from build/tests/core, CS_SOURCE_DIR the worktree
uptime
nice -n 5 ./bench_strain_driver $1 strain:3:$2:1 strain:3:$2:1:0:-1:-1:-1:1 strain:3:$2:1 strain:3:$2:1:0:-1:-1:-1:1
uptime
