#!/bin/bash
# after the callgrind chain: the obstacle's first 4 s (adaptive 5e-4 and fixed 0.5 ms, bin0 and
# bin1) and the flat road with the calibration lattice 0.002 MPa on bin1 (adaptive)
while ! grep -q '^chain-done' /work/rom_data/speed/cg/ir_results.txt; do sleep 5; done
cd /work/wt-speed
D=/work/rom_data/speed/tracks
T=docs/bench/speed_2026-12-07/tracks.sh
for b in bin0 bin1; do
  $T /work/rom_data/speed/$b/bench_strain_driver $D/$b-ada 5e-4 obstacle 4 strain:2
  $T /work/rom_data/speed/$b/bench_strain_driver $D/$b-fixed 0 obstacle 4 strain:2:0.0005
done
$T /work/rom_data/speed/bin1/bench_strain_driver $D/bin1-ada-calq 5e-4 flat-road 9.5 strain:2:0:0:0:-1:-1:-1:-1:-2:-1:-1:0.002
echo done
