#!/bin/sh
# Instruction counts (callgrind, deterministic under load) of the strain leg:
#   ir.sh BINDIR [TAG]
# BINDIR holds bench_strain_step and bench_strain_robot (e.g. build/tests/robot). Prints
#  - one leg pass (csr_strainPrepare + csr_strainFinish, 5 ms steps) without and with the foot
#    in contact: (Ir at 600 steps - Ir at 300 steps) / 300, setup excluded;
#  - eight legs (bench_strain_robot, gaits/flat_road.csv, mu 0.8, bend order 2, Newton to 1e-7,
#    at most 16 passes) at 5 ms and 1 ms: Ir to 2 s - Ir to 1 s (the gait), instructions
#    per simulated second, and the passes per step over 0-2 s.
# STEP_CASES="" skips the one-leg part.
cd "$(dirname "$0")/../../.." || exit 1
export CS_SOURCE_DIR=$PWD
bin=$(cd "$1" && pwd); tag=${2:-run}
out=build/ss/ir_$tag; mkdir -p $out
ir() { # ir NAME CMD...: the total Ir of a run
  name=$1; shift
  valgrind --tool=callgrind --callgrind-out-file=$out/$name.cg "$@" > $out/$name.txt 2>&1
  grep -m1 "^summary:" $out/$name.cg | awk '{print $2}'
}
for c in ${STEP_CASES-0 1}; do
  a=$(ir step_${c}_300 $bin/bench_strain_step 2 $c 300)
  b=$(ir step_${c}_600 $bin/bench_strain_step 2 $c 600)
  echo "$tag: one leg pass, contact $c: $(echo "($b - $a) / 300" | bc) instructions"
done
for h in ${ROBOT_H-0.005 0.001}; do
  a=$(ir robot_${h}_1 $bin/bench_strain_robot gaits/flat_road.csv 0.8 $h 1 2 16 1e-7)
  b=$(ir robot_${h}_2 $bin/bench_strain_robot gaits/flat_road.csv 0.8 $h 2 2 16 1e-7)
  pps=$(grep -o "[0-9]* steps taken.*passes per step" $out/robot_${h}_2.txt)
  echo "$tag: eight legs, h $h s: $(echo "$b - $a" | bc) instructions per simulated s (1-2 s); 0-2 s: $pps"
done
