#!/bin/bash
while ! grep -q '^done3' /work/rom_data/speed9/chain3.log; do sleep 5; done
cd /work/wt-speed9
D=/work/rom_data/speed9/tracks
T=docs/bench/speed9_2026-12-07b/tracks.sh
B=/work/rom_data/speed9/bin3/bench_strain_driver
$T $B $D/bin3-flat 2.5e-4 flat-road 9.5 strain:2
$T $B $D/bin3-obst 2.5e-4 obstacle 4 strain:2
$T $B $D/bin3-flat-repeat 2.5e-4 flat-road 9.5 strain:2
echo done4
