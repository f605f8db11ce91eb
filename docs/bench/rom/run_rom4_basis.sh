#!/usr/bin/env bash
# Session rom4 (docs/notes/rom.md): the basis size on all 34 training rays. For each N given,
# the mixed basis with N POD modes (+ 48 pressure modes and their 48 supremizers) and the
# held-out check of T_H4 and T_S2 with every element. From the repository root; arguments SNAP
# (a directory linking mesh.h5, the 34 training rays and the held-out rays: session rom3's
# snap_b34), OUT, then the sizes N. CS (environment) is the crawlsim binary.
set -euo pipefail
SNAP=$1
OUT=$2
shift 2
CS=${CS:-$PWD/build/tools/crawlsim}
EX=(--actuator leg --set S1=15 --set S2=15 --set S3=15)
export OMP_WAIT_POLICY=PASSIVE OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
for n in "$@"; do
  D=$OUT/b34n$n
  mkdir -p "$D"
  if [ ! -s "$D/basis_mixed.h5" ]; then
    /usr/bin/python3 tools/rom_basis.py "$SNAP" --n "$n" --m 48 --mixed \
      --out "$D/basis_mixed.h5" > "$D/basis_mixed.log" 2>&1
  fi
  if [ ! -s "$D/check_all_elements.log" ] || ! grep -q 'rays checked' "$D/check_all_elements.log"; then
    /usr/bin/time -v "$CS" rom check --snapshots "$SNAP" --basis "$D/basis_mixed.h5" \
      --ray T_H4 --ray T_S2 "${EX[@]}" > "$D/check_all_elements.log" 2> "$D/check_all_elements.time"
  fi
done
