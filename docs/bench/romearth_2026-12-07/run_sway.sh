#!/bin/bash
# run_sway.sh: the Earth stance's sway-buckling load by the rod, the rom and the FE
# (docs/notes/rom.md "The Earth stance's sway-buckling load, FE-informed"; `crawlsim rom sway`).
#   bash docs/bench/romearth_2026-12-07/run_sway.sh BUILD LEG OUT
# BUILD: the build folder (crawlsim in BUILD/tools), LEG: a fibre-basis leg file (romreal7's
# leg_v13f104m24.h5: `crawlsim rom leg-file` on b96_v13f104m24.h5, docs/notes/rom.md "Held-out
# cases to full load"), OUT: a folder for the logs and CSVs. CPU on 2026-12-07 under load 9-11:
# the rod < 1 s, the FE ~10 s per load, the rom 4-80 s per load to 0.4 N (slow past its
# cantilever load).
set -e
B=${1:?build folder}; LEG=${2:?leg file}; OUT=${3:?output folder}
mkdir -p "$OUT"
C="$B/tools/crawlsim"
uptime > "$OUT/uptime.txt"
# the rod at its shipped 4 elements per segment, 16 and 64 (the foot's frame is the last element's)
L=""; for p in 0 0.2 0.4 0.6 0.8 1.0 1.05 1.1 1.15 1.2 1.3; do L="$L --load $p"; done
for n in 4 16 64; do
  "$C" rom sway --rod-elements $n $L --out "$OUT/sway_rod_e$n.csv" > "$OUT/sway_rod_e$n.log"
done
# the full FE on the leg file's own mesh and model
L=""; for p in 0 0.2 0.4 0.6 0.8 1.0 1.1 1.2 1.3; do L="$L --load $p --fe-load $p"; done
nice -n 5 "$C" rom sway --leg-file "$LEG" --skip-rom $L --out "$OUT/sway_fe_sweep.csv" \
  > "$OUT/sway_fe_sweep.log" 2>&1
# the reduced model (slow: run last; resumable only level by level, each from 0 N)
nice -n 5 "$C" rom sway --leg-file "$LEG" --load 0 --load 0.2 --load 0.4 \
  --out "$OUT/sway_rom.csv" > "$OUT/sway_rom.log" 2>&1
# the reduced model straight from 0 to the stance's 0.8 N
nice -n 5 "$C" rom sway --leg-file "$LEG" --load 0.8 --out "$OUT/sway_rom08.csv" \
  > "$OUT/sway_rom08.log" 2>&1
# the FE's discretisation: the leg meshed afresh at l_soft 8 (the leg file's mesh again), 6, 4, 3
for l in 8 6 4 3; do
  nice -n 5 "$C" rom sway --fe-mesh-size $l --work "$OUT" --load 0.8 --fe-load 0.8 \
    --fe-load 1.1 --fe-load 1.2 --out "$OUT/sway_fe_l$l.csv" > "$OUT/sway_fe_l$l.log" 2>&1
done
# what the fibres add: the FE without them
nice -n 5 "$C" rom sway --fe-mesh-size 8 --fe-fibres 0 --work "$OUT" --load 0 --fe-load 0 \
  --fe-load 0.6 --fe-load 0.8 --fe-load 0.9 --fe-load 1.0 --fe-load 1.1 \
  --out "$OUT/sway_fe_l8_nofibres.csv" > "$OUT/sway_fe_l8_nofibres.log" 2>&1
