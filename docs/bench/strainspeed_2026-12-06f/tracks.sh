#!/bin/sh
# tracks.sh BASE_BIN NEW_BIN OUTDIR [T]: the flat road (scene defaults, strain level's defaults,
# backward Euler) for T s (default 9) at 5 ms and 1 ms, the base and the new binary one after the
# other (base, new, base, new: their CPU seconds interleaved under the same load), each run's file
# kept in OUTDIR (CS_BENCH_KEEP), then ../kernel_2026-12-06/tracks.py compares every float
# dataset of the run files (bit-identical or not, the largest support distance). Run from the
# worktree's root; prints the bench lines and the comparisons.
root=$(pwd); here=$(cd "$(dirname "$0")" && pwd); base=$1; new=$2; out=$3; T=${4:-9}
mkdir -p "$out/base" "$out/new"
export CS_SOURCE_DIR=$root
cd build/tests/core || exit 1
uptime
for H in 0.005 0.001; do
  for w in base new; do
    bin=$base; [ $w = new ] && bin=$new
    echo "== $w h $H"
    CS_BENCH_KEEP=$out/$w nice -n 5 "$bin" "$T" strain:2:$H:1 | grep -E "flat-road|tree:|legs:|pneumatics"
  done
done
uptime
for f in "$out"/base/*.h5; do
  echo "== $(basename "$f")"
  /usr/bin/python3 "$here/../kernel_2026-12-06/tracks.py" "$f" "$out/new/$(basename "$f")"
done
