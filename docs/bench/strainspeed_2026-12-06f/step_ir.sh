#!/bin/sh
# step_ir.sh BIN TAG [BEND]: instructions of one strain-leg step (csr_strainPrepare +
# csr_strainFinish, one pass, 5 ms, base held; bench_strain_step), without and with the foot in
# contact: (Ir at 400 steps - Ir at 200 steps) / 200, setup excluded. BEND the bend order
# (1: the default --links 2). Appends "TAG bend B contact C: N" to step_ir.txt beside this script.
here=$(cd "$(dirname "$0")" && pwd); bin=$1; tag=$2; bend=${3:-1}
tmp=$(mktemp -d)
for c in 0 1; do
  for s in 200 400; do
    nice -n 5 valgrind --tool=callgrind --callgrind-out-file=$tmp/$c.$s.cg "$bin" $bend $c $s > /dev/null 2>&1
  done
  a=$(grep -m1 "^summary:" $tmp/$c.200.cg | awk '{print $2}'); b=$(grep -m1 "^summary:" $tmp/$c.400.cg | awk '{print $2}')
  echo "$tag bend $bend contact $c: $(( (b - a) / 200 )) instructions per leg step" | tee -a "$here/step_ir.txt"
done
rm -rf "$tmp"
