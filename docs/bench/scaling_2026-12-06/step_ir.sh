#!/bin/sh
# Instruction counts (callgrind) of one strain-leg pass against its modes:
#   step_ir.sh BINDIR [ARGS...]   ARGS: "BEND CONTACT AXIAL JOINT SHEAR NSUB" cases, one per word
#                                 group separated by commas (default: the table's cases)
# Each case: (Ir at 400 steps - Ir at 200 steps) / 200 of bench_strain_step (5 ms steps, one
# pass each, setup excluded), and the leg's unknowns. Outputs under build/ss/scaling/.
cd "$(dirname "$0")/../../.." || exit 1
export CS_SOURCE_DIR=$PWD
bin=$(cd "$1" && pwd); out=build/ss/scaling; mkdir -p $out
cases=${2:-"0 0 0 0 1 4,0 1 0 0 1 4,1 0 0 0 1 4,1 1 0 0 1 4,2 0 0 0 1 4,2 1 0 0 1 4,3 0 0 0 1 4,3 1 0 0 1 4,2 1 1 0 1 4,2 1 0 -1 1 4,2 1 0 0 0 4,2 1 0 0 1 2,1 1 0 -1 0 2"}
ir() { name=$1; shift; valgrind --tool=callgrind --callgrind-out-file=$out/$name.cg "$@" > $out/$name.txt 2>&1
       grep -m1 "^summary:" $out/$name.cg | awk '{print $2}'; }
echo "$cases" | tr ',' '\n' | while read b c a j s n; do
  tag=b${b}c${c}a${a}j${j}s${s}n${n}
  x=$(ir ${tag}_200 $bin/bench_strain_step $b $c 200 $a $j $s $n)
  y=$(ir ${tag}_400 $bin/bench_strain_step $b $c 400 $a $j $s $n)
  u=$(grep -o '[0-9]* unknowns' $out/${tag}_400.txt)
  echo "bend $b contact $c axial $a joint $j shear $s nsub $n: $u, $(echo "($y - $x) / 200" | bc) instructions per pass"
done
