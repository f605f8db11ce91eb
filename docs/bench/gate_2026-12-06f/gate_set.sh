#!/bin/sh
# usage: gate_set.sh RUN...: issue 33's obstacle robustness set with the library's landing gate
# (the scene's default, gaits/obstacle.gate), one run after the other, nice 5, resumable (a run
# whose RUN.txt exists here is skipped). RUN: nominal (35 s, as the open-loop record), ramp0.1,
# ramp0.5 (47 s), mu0.6, mu1.0, m25g, m75g, tau0.5x, tau2x, dt_half (36 s: the table ends later
# by its holds), as docs/bench/obst_2026-12-06e/gate2.py's RUNS; nominal_open: --gate none.
# GATE=FILE|none: another gate (files RUN_GATEBASENAME.*). The HDF5 files go to $OUT
# (default /work/rom_data/gate; not kept); RUN.txt is score.py's lines, RUN.log the run's
# summary with CPU and wall time.
cd "$(dirname "$0")/../../.."
B=docs/bench/gate_2026-12-06f
OUT=${OUT:-/work/rom_data/gate}
mkdir -p "$OUT"
for n in "$@"; do
  T=36; a=
  case $n in
    nominal) T=35 ;;
    nominal_open) T=35; a="--gate none" ;;
    ramp0.1) a="--ramp 0.1" ;;
    ramp0.5) T=47; a="--ramp 0.5" ;;
    mu0.6) a="--friction 0.6" ;;
    mu1.0) a="--friction 1.0" ;;
    m25g) a="--support-mass 0.025" ;;
    m75g) a="--support-mass 0.075" ;;
    tau0.5x) a="--tau 0.01" ;;
    tau2x) a="--tau 0.04" ;;
    dt_half) a="--dt 0.0005" ;;
    *) echo "gate_set.sh: unknown run $n" >&2; exit 2 ;;
  esac
  tag=$n; [ -n "$GATE" ] && { a="$a --gate $GATE"; tag=${n}_$(basename "$GATE" .gate); }
  [ -s $B/$tag.txt ] && continue
  /usr/bin/time -f "%U s user, %e s wall" nice -n 5 build/tools/crawlsim run --scene obstacle \
    --t-end $T $a --out "$OUT/$tag.h5" > $B/$tag.log 2>&1
  /usr/bin/python3 $B/score.py "$OUT/$tag.h5" > $B/$tag.txt
done
