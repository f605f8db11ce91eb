#!/bin/sh
# rom15's Newton screens on the corotated manifold (r = 12, k = 176), one after the other;
# a case whose log already holds its last step is skipped (rerun to resume the list).
#   sh docs/bench/rom15_2026-12-07h/run_screens.sh CASE...   CASE = RAY:T:PK:SUP[:STEPS]
# PK the pressure enrichment modes (pressure_enrich.py's; 0: the basis' P alone), SUP 1 = their
# supremizers as local modes, SUP 2 = theirs and the basis' 48 of P (rom10's, V's last 48);
# env K the local modes (176), TAG a suffix of the log names. Logs
# newton_pk<PK>[s|ss][TAG]_<RAY>_t<T>.log beside this script.
S=/work/rom_data/rom11/snap B=/work/rom_data/rom11/b176_f104.h5 L=/work/rom_data/rom11/legf/leg.h5
O=/work/rom_data/rom14 R=/work/rom_data/rom15 D=$(dirname "$0")
E=${PENRICH:-$R/penrich_r12k176.h5} K=${K:-176}
for c in "$@"; do
  ray=$(echo "$c" | cut -d: -f1); t=$(echo "$c" | cut -d: -f2); pk=$(echo "$c" | cut -d: -f3)
  sup=$(echo "$c" | cut -d: -f4); n=$(echo "$c" | cut -d: -f5); n=${n:-12}
  tag=pk$pk; extra=""
  if [ "$sup" = 1 ]; then tag=${tag}s; extra="--psup --sup $pk"; fi
  # SUP 2: also the basis' own 48 supremizers of P (V's columns before the added ones)
  if [ "$sup" = 2 ]; then tag=${tag}ss; extra="--psup --sup $((pk + 48))"; fi
  [ -n "$TAG" ] && tag=$tag$TAG
  log=$D/newton_${tag}_${ray}_t$t.log
  if grep -q "Newton $n " "$log" 2>/dev/null; then continue; fi
  echo "== $c ($(date -u +%H:%M:%S), load $(cut -d' ' -f1-3 /proc/loadavg))" > "$log"
  nice -n 5 /usr/bin/python3 "$D/corot_newton_p.py" --penrich "$E" --pk "$pk" $extra \
    $S $B $L $O/rod_w2.h5 $O/rod_w2_local_r12.h5 --r 12 --k "$K" --ray "$ray" --t "$t" \
    --newton "$n" --bfgs --save "$R/newton_${tag}_${ray}_t$t.npy" >> "$log" 2>&1
  echo "== done ($(date -u +%H:%M:%S), load $(cut -d' ' -f1-3 /proc/loadavg))" >> "$log"
done
