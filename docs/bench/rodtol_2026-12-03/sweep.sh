#!/bin/bash
# --rod-tol sweep of the 9 s flat road on rod legs (Gauss-Seidel), bench_flatroad; error = max
# |x - reference| at whole seconds, reference = the staggered 25 µs run (README "Rod legs")
ref="8.60 41.01 77.12 113.85 150.23 186.58 222.92 259.24 295.56"
B=${B:-build/tests/core/bench_flatroad}
for n in 4 2; do for m in 1 2; do for ts in 1 2 5 10 20 50; do
  out=$(CS_SOURCE_DIR=${CS_SOURCE_DIR:-.} nice $B rod $n 0.001 9 - gs $m 1 $ts 2>&1)
  rtf=$(echo "$out" | grep -o 'CPU [0-9.]* s -> real-time factor [0-9.]*' | awk '{print $NF}')
  xs=$(echo "$out" | grep 'x at whole' | sed 's/.*(mm)://')
  st=$(echo "$out" | grep -c stopped)
  err=$(python3 -c "
r=[float(v) for v in '$ref'.split()]; x=[float(v) for v in '$xs'.split()]
print('%.2f'%max(abs(a-b) for a,b in zip(r,x)) if len(x)==9 else 'n/a')")
  steps=$(echo "$out" | grep -o 'per leg advance: [0-9.]* CVODE steps' | awk '{print $4}')
  echo "n=$n H=${m}ms tol=$ts rtf=$rtf err_mm=$err steps=$steps stopped=$st x9=$(echo $xs | awk '{print $NF}')"
done; done; done
