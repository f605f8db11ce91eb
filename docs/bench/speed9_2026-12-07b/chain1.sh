#!/bin/bash
while ! grep -q '^done0' /work/rom_data/speed9/chain0.log; do sleep 5; done
cd /work/wt-speed9
D=/work/rom_data/speed9/tracks
T=docs/bench/speed9_2026-12-07b/tracks.sh
B=/work/rom_data/speed9/bin1/bench_strain_driver
$T $B $D/bin1-flat 2.5e-4 flat-road 9.5 strain:2
$T $B $D/bin1-obst 2.5e-4 obstacle 4 strain:2
docs/bench/speed9_2026-12-07b/cg.sh $B bin1.ada 1 1 strain:2 2.5e-4 1
echo done1
