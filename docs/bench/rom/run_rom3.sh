#!/usr/bin/env bash
# Session rom3 (docs/notes/rom.md): the short leg's mixed reduced model on a chosen set of
# training rays, hyper-reduced by the incremental-Cholesky NNLS, checked on the held-out rays
# with every element and with the weights, from the repository root after a Release build and
# the production (run_short_production.sh, into SNAP). Arguments: SNAP (the production's
# directory), OUT (a new directory), then the training rays; the held-out T_H4 and T_S2 are
# linked as well. The ECSW matrix takes every STRIDE-th training state (environment, default 1).
set -euo pipefail
SNAP=$1
OUT=$2
shift 2
STRIDE=${STRIDE:-1}
CS=$PWD/build/tools/crawlsim
EX=(--actuator leg --set S1=15 --set S2=15 --set S3=15)
mkdir -p "$OUT/snap"
for r in mesh "$@" T_H4 T_S2; do ln -sf "$(realpath "$SNAP/$r.h5")" "$OUT/snap/$r.h5"; done
export OMP_WAIT_POLICY=PASSIVE
/usr/bin/python3 tools/rom_basis.py "$OUT/snap" --turns --tol 1e-12 --mixed \
  --out "$OUT/basis_mixed.h5" | tee "$OUT/basis_mixed.log"
nice -n 5 "$CS" rom ecsw-matrix --basis "$OUT/basis_mixed.h5" --out "$OUT/ecsw_matrix.h5" \
  --stride "$STRIDE" --work "$OUT" "${EX[@]}" | tee "$OUT/ecsw_matrix.log"
/usr/bin/python3 tools/rom_ecsw.py "$OUT/ecsw_matrix.h5" --out "$OUT/weights.h5" \
  --tol 1e-2 --tol 1e-3 --tol 1e-4 | tee "$OUT/ecsw.log"
nice -n 5 "$CS" rom check --snapshots "$OUT/snap" --basis "$OUT/basis_mixed.h5" --ray T_H4 \
  --ray T_S2 "${EX[@]}" | tee "$OUT/check_all_elements.log"
for t in 1e-2 1e-3 1e-4; do
  nice -n 5 "$CS" rom check --snapshots "$OUT/snap" --basis "$OUT/basis_mixed.h5" \
    --weights "$OUT/weights_tol$t.h5" --ray T_H4 --ray T_S2 "${EX[@]}" \
    | tee "$OUT/check_tol$t.log"
done
