#!/bin/bash
while ! grep -q '^done2' /work/rom_data/speed9/chain2.log; do sleep 5; done
cd /work/wt-speed9
D=/work/rom_data/speed9/tracks
T=docs/bench/speed9_2026-12-07b/tracks.sh
B=/work/rom_data/speed9/bin2/bench_strain_driver
docs/bench/speed9_2026-12-07b/cg.sh $B bin2.ada 1 1 strain:2 2.5e-4 1
$T $B $D/bin2-flat 2.5e-4 flat-road 9.5 strain:2
$T $B $D/bin2-obst 2.5e-4 obstacle 4 strain:2
$T $B $D/bin2-flat-repeat 2.5e-4 flat-road 9.5 strain:2
echo done3
