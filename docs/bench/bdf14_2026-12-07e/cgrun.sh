#!/bin/sh
# cgrun.sh BIN PREFIX: BDF2 at 5e-4 and backward Euler (default) at 2.5e-4, window [1,2] s
export CG_OUT=/tmp/bdf14/cg
S=/work/wt-bdf14/docs/bench/speed_2026-12-07/cg.sh
[ -f $CG_OUT/$2.o2.5e-4.cg ] || $S $1 $2.o2.5e-4 1 1 strain:2:0:2 5e-4 1
[ -f $CG_OUT/$2.o1.2.5e-4.cg ] || $S $1 $2.o1.2.5e-4 1 1 strain:2 2.5e-4 1
