#!/bin/sh
# Instruction counts (callgrind) of the strain leg's kernel, one build:
#   ir.sh BINDIR TAG
# BINDIR holds bench_strain_step and bench_strain_robot (e.g. build/tests/robot). Prints
#  - one leg pass (csr_strainPrepare + csr_strainFinish, 5 ms steps) without and with the foot
#    in contact: (Ir at 600 steps - Ir at 300 steps) / 300, setup excluded;
#  - eight legs (bench_strain_robot, gaits/flat_road.csv, mu 0.8, bend order 2, Newton to 1e-7,
#    at most 16 passes, 5 ms): Ir of 0-1 s, and Ir to 2 s - Ir to 1 s (the gait).
# Outputs under build/ss/TAG/.
cd "$(dirname "$0")/../../.." || exit 1
export CS_SOURCE_DIR=$PWD
bin=$(cd "$1" && pwd); tag=$2; out=build/ss/$tag; mkdir -p $out
ir() { name=$1; shift; valgrind --tool=callgrind --callgrind-out-file=$out/$name.cg "$@" > $out/$name.txt 2>&1
       grep -m1 "^summary:" $out/$name.cg | awk '{print $2}'; }
for c in 0 1; do
  a=$(ir step_${c}_300 $bin/bench_strain_step 2 $c 300); b=$(ir step_${c}_600 $bin/bench_strain_step 2 $c 600)
  echo "$tag: one leg pass, contact $c: $(echo "($b - $a) / 300" | bc) instructions"
done
a=$(ir robot_1 $bin/bench_strain_robot gaits/flat_road.csv 0.8 0.005 1 2 16 1e-7)
echo "$tag: eight legs 0-1 s: $a instructions total; $(grep -o '[0-9]* steps taken.*passes per step' $out/robot_1.txt)"
b=$(ir robot_2 $bin/bench_strain_robot gaits/flat_road.csv 0.8 0.005 2 2 16 1e-7)
echo "$tag: eight legs 1-2 s: $(echo "$b - $a" | bc) instructions per simulated s; 0-2 s: $(grep -o '[0-9]* steps taken.*passes per step' $out/robot_2.txt)"
