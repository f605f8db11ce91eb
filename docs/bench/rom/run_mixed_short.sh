#!/usr/bin/env bash
# The mixed reduced model of the short leg end to end (docs/notes/rom.md, session rom2), from the
# repository root after a Release build and the production (run_short_production.sh): the mixed
# basis on every finished training ray and its quarter turns, the ECSW rows of the mixed model,
# the weights, the checks (held out, unreduced and hyper-reduced) and the eigenfrequencies at 0
# and 0.15 MPa (the FE's statics to 0.15 MPa: one FE process; pause the production meanwhile).
# OUT as argument (default build/rom_mixed), TOL the ECSW tolerance (default 1e-3).
set -euo pipefail
S=build/rom_short
D=${1:-build/rom_mixed}
TOL=${2:-1e-3}
EX=(--actuator leg --set S1=15 --set S2=15 --set S3=15)
CS=build/tools/crawlsim
mkdir -p "$D"
/usr/bin/python3 tools/rom_basis.py "$S" --turns --tol 1e-12 --mixed --out "$D/basis_mixed.h5" \
  | tee "$D/basis_mixed.log"
nice -n 5 "$CS" rom modes --basis "$D/basis_mixed.h5" --out "$D/modes.h5" --work "$D" "${EX[@]}"
/usr/bin/python3 tools/rom_modes.py "$D/modes.h5" "$S" "$D/basis_mixed.h5" | tee "$D/modes.log"
# the same with the FE's eight lowest vibration modes at rest in the basis
/usr/bin/python3 tools/rom_basis.py "$S" --turns --tol 1e-12 --mixed --vib "$D/modes.h5" \
  --nvib 8 --out "$D/basis_mixed_vib.h5" | tee "$D/basis_mixed_vib.log"
nice -n 5 "$CS" rom modes --rom-only --basis "$D/basis_mixed_vib.h5" --out "$D/modes_vib.h5" \
  --work "$D" "${EX[@]}"
/usr/bin/python3 tools/rom_modes.py "$D/modes_vib.h5" "$S" "$D/basis_mixed_vib.h5" \
  --fe "$D/modes.h5" | tee "$D/modes_vib.log"
nice -n 5 "$CS" rom check --snapshots "$S" --basis "$D/basis_mixed.h5" "${EX[@]}" \
  | tee "$D/check_mixed.log"
nice -n 5 "$CS" rom ecsw-matrix --basis "$D/basis_mixed.h5" --out "$D/ecsw_matrix.h5" \
  --work "$D" "${EX[@]}"
/usr/bin/python3 tools/rom_ecsw.py "$D/ecsw_matrix.h5" --out "$D/weights.h5" --tol "$TOL" \
  | tee "$D/ecsw.log"
nice -n 5 "$CS" rom check --snapshots "$S" --basis "$D/basis_mixed.h5" --weights "$D/weights.h5" \
  --all "${EX[@]}" | tee "$D/check_mixed_ecsw.log"
