#!/bin/sh
# Instructions per simulated second of the flat road through the driver (callgrind):
#   ir_driver.sh BENCH_STRAIN_DRIVER [TAG] [DT...]   (default DT: 0.005 0.001)
# bench_strain_driver T strain:3:DT (cs_run with its output, the scene's defaults) to 1 s and
# to 2 s; the difference is one second of gait (the driver's whole step: legs, tree solve,
# ODE, pneumatics, output).
cd "$(dirname "$0")/../../.." || exit 1
export CS_SOURCE_DIR=$PWD
bin=$(cd "$(dirname "$1")" && pwd)/$(basename "$1"); tag=${2:-run}
shift; [ $# -gt 0 ] && shift
out=build/ss/ird_$tag; mkdir -p $out
ir() {
  name=$1; shift
  valgrind --tool=callgrind --callgrind-out-file=$out/$name.cg "$@" > $out/$name.txt 2>&1
  grep -m1 "^summary:" $out/$name.cg | awk '{print $2}'
}
dts=${*:-0.005 0.001}
for h in $dts; do
  a=$(ir run_${h}_1 $bin 1 strain:3:$h)
  b=$(ir run_${h}_2 $bin 2 strain:3:$h)
  echo "$tag: driver, flat road, h $h s: $(echo "$b - $a" | bc) instructions per simulated s (1-2 s)"
done
