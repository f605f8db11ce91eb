#!/bin/bash
# waits for the tracks, then the callgrind profiles one after the other (base, then new)
while ! grep -q '^done' /work/rom_data/speed/tracks.log; do sleep 5; done
cd /work/wt-speed/docs/bench/speed_2026-12-07
for b in bin0 bin1; do
  ./cg.sh /work/rom_data/speed/$b/bench_strain_driver $b.ada 1 2 strain:2 5e-4 0
  ./cg.sh /work/rom_data/speed/$b/bench_strain_driver $b.fixed.0 0.5 1 strain:2:0.0005 0 0
  ./cg.sh /work/rom_data/speed/$b/bench_strain_driver $b.fixed.1 0.5 1 strain:2:0.0005 0 1
done
echo chain-done >> /work/rom_data/speed/cg/ir_results.txt
