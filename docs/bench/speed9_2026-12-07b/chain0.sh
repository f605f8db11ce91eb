#!/bin/bash
cd /work/wt-speed9
D=/work/rom_data/speed9/tracks
T=docs/bench/speed9_2026-12-07b/tracks.sh
B=/work/rom_data/speed9/bin0/bench_strain_driver
$T $B $D/bin0-flat 2.5e-4 flat-road 9.5 strain:2
$T $B $D/bin0-obst 2.5e-4 obstacle 4 strain:2
docs/bench/speed9_2026-12-07b/cg.sh $B bin0.ada 1 1 strain:2 2.5e-4 1
echo done0
