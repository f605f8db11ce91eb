#!/usr/bin/env bash
# Session romsweep (docs/notes/rom.md, "The sweep at 300x"): the 0-0.4 MPa bend sweep of the
# short leg (Omega1 & Omega2 in every segment, rows every 0.05 MPa) by the full FE and by
# `bend --model rom --rom-file` on each leg file, one after the other in one run, each command
# under /usr/bin/time (its CPU seconds), the load (uptime) between; then the every-element
# reduced model on REF_BASIS (the accuracy reference: --rom-basis, every element at weight 1;
# "none" skips it and REF_H5 must exist) and romsweep_compare.py's table. From the repository
# root after a Release build. Arguments OUT, REF_BASIS|none, LEG.h5... CS: the crawlsim binary.
set -euo pipefail
OUT=$1
REF=$2
shift 2
CS=${CS:-$PWD/build/tools/crawlsim}
HERE=$(dirname "$0")
LEG=(--actuator leg --set S1=15 --set S2=15 --set S3=15 --chambers 1,2)
EX=("${LEG[@]}" --p-max 0.4 --p-step 0.05)
export OMP_WAIT_POLICY=PASSIVE OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
mkdir -p "$OUT"
echo "== load before the FE: $(uptime)"
/usr/bin/time -f '== fe: %e s wall, %U s user, %S s system, %M kB' "$CS" bend --model fe \
  --mesh-symmetric 1 --mesh-size 8 --threads 1 "${EX[@]}" --out "$OUT/bend_fe.h5" 2>&1
echo "== load after the FE: $(uptime)"
files=()
k=0
for leg in "$@"; do
  k=$((k + 1))
  /usr/bin/time -f "== rom $leg: %e s wall, %U s user, %S s system, %M kB" "$CS" bend \
    --model rom --rom-file "$leg" "${EX[@]}" --out "$OUT/bend_rom_$k.h5" 2>&1
  echo "== load after it: $(uptime)"
  files+=("$OUT/bend_rom_$k.h5")
done
if [ "$REF" != none ]; then
  /usr/bin/time -f "== rom reference (every element) $REF: %e s wall, %U s user" "$CS" bend \
    --model rom --rom-basis "$REF" "${EX[@]}" --out "$OUT/bend_rom_ref.h5" 2>&1
  echo "== load at the end: $(uptime)"
fi
/usr/bin/python3 "$HERE/romsweep_compare.py" "$OUT/bend_fe.h5" "$OUT/bend_rom_ref.h5" \
  "${files[@]}"
