#!/usr/bin/env bash
# The reduced-order FE leg's offline stages end to end (docs/notes/rom.md), from the repository
# root after a Release build: snapshots (resumable: run again to continue), basis, element
# weights, and the check against the held-out rays. DIR and the mesh size as arguments
# (defaults: rom_snapshots_l8, 8 mm, the leg). Extra crawlsim options (e.g. --set S1=15) after
# them go to every crawlsim stage.
set -euo pipefail
DIR=${1:-rom_snapshots_l8}
L=${2:-8}
shift $(( $# > 2 ? 2 : $# )) || true
EXTRA=("$@")
CS=build/tools/crawlsim
export OMP_WAIT_POLICY=PASSIVE
nice -n 10 "$CS" rom snapshots --out "$DIR" --mesh-size "$L" --threads 1 "${EXTRA[@]}"
/usr/bin/python3 tools/rom_basis.py "$DIR" --tol 1e-3 | tee "$DIR/basis.log"
"$CS" rom ecsw-matrix --basis "$DIR/basis.h5" --out "$DIR/ecsw_matrix.h5" --work "$DIR" \
  "${EXTRA[@]}"
/usr/bin/python3 tools/rom_ecsw.py "$DIR/ecsw_matrix.h5" --out "$DIR/weights.h5" --tol 1e-3 \
  | tee "$DIR/ecsw.log"
"$CS" rom check --snapshots "$DIR" --basis "$DIR/basis.h5" "${EXTRA[@]}" | tee "$DIR/check.log"
"$CS" rom check --snapshots "$DIR" --basis "$DIR/basis.h5" --weights "$DIR/weights.h5" \
  "${EXTRA[@]}" | tee "$DIR/check_ecsw.log"
# the mixed reduced model (docs/notes/rom.md, stage 6): pressure basis and supremizers, checked
# unreduced (its hyper-reduction is not fitted yet)
/usr/bin/python3 tools/rom_basis.py "$DIR" --tol 1e-3 --mixed --out "$DIR/basis_mixed.h5" \
  | tee "$DIR/basis_mixed.log"
"$CS" rom check --snapshots "$DIR" --basis "$DIR/basis_mixed.h5" "${EXTRA[@]}" \
  | tee "$DIR/check_mixed.log"
