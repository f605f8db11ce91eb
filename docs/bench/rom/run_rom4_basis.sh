#!/usr/bin/env bash
# Session rom4 (docs/notes/rom.md): the basis size on all 34 training rays. For each N given,
# the mixed basis with N POD modes (+ 48 pressure modes and their 48 supremizers) and the
# held-out check of T_H4 and T_S2 with every element. From the repository root; arguments SNAP
# (a directory linking mesh.h5, the 34 training rays and the held-out rays: session rom3's
# snap_b34), OUT, then the sizes N. Environment: CS the crawlsim binary, M the pressure basis
# size (default 48; another M goes to b34n<N>m<M>), RAYS the held-out rays (default T_H4 T_S2).
set -euo pipefail
SNAP=$1
OUT=$2
shift 2
CS=${CS:-$PWD/build/tools/crawlsim}
M=${M:-48}
read -r -a RAYS <<< "${RAYS:-T_H4 T_S2}"
RA=()
for r in "${RAYS[@]}"; do RA+=(--ray "$r"); done
EX=(--actuator leg --set S1=15 --set S2=15 --set S3=15)
export OMP_WAIT_POLICY=PASSIVE OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
for n in "$@"; do
  D=$OUT/b34n$n
  [ "$M" != 48 ] && D=$OUT/b34n${n}m$M
  mkdir -p "$D"
  if [ ! -s "$D/basis_mixed.h5" ]; then
    /usr/bin/python3 tools/rom_basis.py "$SNAP" --n "$n" --m "$M" --mixed \
      --out "$D/basis_mixed.h5" > "$D/basis_mixed.log" 2>&1
  fi
  C=$D/check_all_elements.log
  if [ ! -s "$C" ] || ! grep -q 'rays checked' "$C"; then
    /usr/bin/time -v stdbuf -oL "$CS" rom check --snapshots "$SNAP" --basis "$D/basis_mixed.h5" \
      "${RA[@]}" "${EX[@]}" > "$C" 2> "$D/check_all_elements.time"
  fi
done
