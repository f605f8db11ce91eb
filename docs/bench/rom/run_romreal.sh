#!/usr/bin/env bash
# Session romreal (docs/notes/rom.md, "The real leg's rom"): the robot's own leg (paper
# geometry, l_soft 8 mm, symmetric mesh) reduced from the rays of run_leg_production.sh.
# From the repository root after a Release build. Arguments: SNAP (a directory linking mesh.h5,
# the training rays and the held-out T_H4 and T_S2), D (the basis directory: D/basis_mixed.h5
# of tools/rom_basis.py SNAP --turns --n N --m M --mixed), then the stages to run, in order:
#   check     the held-out rays with every element            -> D/check_all_elements.log
#   matrix    the ECSW matrices, every STRIDE-th training state -> D/ecsw_matrix.h5
#   fit       the ECSW weights at TOL (default 1e-2)           -> D/weights_tol<t>.h5
#   wcheck    the held-out rays with the weights of TOL        -> D/check_tol<t>.log
#   legfile   the leg file with the weights of TOL             -> D/leg_tol<t>.h5
# Each stage is skipped when its output exists (resumable). Environment: CS the crawlsim binary,
# STRIDE (default 5: with --turns the states come in four blocks of the FE states, ray by ray
# and four loads per ray, so a stride of 4 would take only every ray's first load), TOL.
set -euo pipefail
SNAP=$1
D=$2
shift 2
CS=${CS:-$PWD/build/tools/crawlsim}
STRIDE=${STRIDE:-5}
TOL=${TOL:-1e-2}
B=$D/basis_mixed.h5
export OMP_WAIT_POLICY=PASSIVE OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
T=(/usr/bin/time -f '%e s wall, %U s user, %M kB resident')
for stage in "$@"; do
  uptime
  case $stage in
    check)
      [ -s "$D/check_all_elements.log" ] && grep -q 'rays checked' "$D/check_all_elements.log" ||
        "${T[@]}" stdbuf -oL "$CS" rom check --snapshots "$SNAP" --basis "$B" --ray T_H4 \
          --ray T_S2 --actuator leg > "$D/check_all_elements.log" 2>&1 ;;
    matrix)
      [ -s "$D/ecsw_matrix.h5" ] ||
        "${T[@]}" "$CS" rom ecsw-matrix --basis "$B" --out "$D/ecsw_matrix.h5" \
          --stride "$STRIDE" --work "$D" --actuator leg > "$D/ecsw_matrix.log" 2>&1 ;;
    fit)
      [ -s "$D/weights_tol$TOL.h5" ] ||
        "${T[@]}" /usr/bin/python3 tools/rom_ecsw.py "$D/ecsw_matrix.h5" \
          --out "$D/weights_tol$TOL.h5" --tol "$TOL" > "$D/ecsw_tol$TOL.log" 2>&1 ;;
    wcheck)
      [ -s "$D/check_tol$TOL.log" ] && grep -q 'rays checked' "$D/check_tol$TOL.log" ||
        "${T[@]}" stdbuf -oL "$CS" rom check --snapshots "$SNAP" --basis "$B" \
          --weights "$D/weights_tol$TOL.h5" --ray T_H4 --ray T_S2 --actuator leg \
          > "$D/check_tol$TOL.log" 2>&1 ;;
    legfile)
      [ -s "$D/leg_tol$TOL.h5" ] ||
        "${T[@]}" "$CS" rom leg-file --basis "$B" --weights "$D/weights_tol$TOL.h5" \
          --out "$D/leg_tol$TOL.h5" --work "$D" --actuator leg > "$D/legfile_tol$TOL.log" 2>&1 ;;
    *) echo "run_romreal.sh: unknown stage $stage" >&2; exit 2 ;;
  esac
done
uptime
