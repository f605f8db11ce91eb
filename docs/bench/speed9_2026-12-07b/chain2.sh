#!/bin/bash
while ! grep -q '^done1' /work/rom_data/speed9/chain1.log; do sleep 5; done
cd /work/wt-speed9
D=/work/rom_data/speed9/tracks
T=docs/bench/speed9_2026-12-07b/tracks.sh
B=/work/rom_data/speed9/bin1/bench_strain_driver
$T $B $D/bin1-flat-repeat 2.5e-4 flat-road 9.5 strain:2
echo done2
