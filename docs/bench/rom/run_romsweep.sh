#!/usr/bin/env bash
# Session romsweep (docs/notes/rom.md, "The sweep at 300x"): the short leg's reduced models for
# the 0-0.4 MPa bend sweep, from the FE production to the leg files, then the timed sweep. From
# the repository root after a Release build. DATA is the data directory (outside git); each stage
# is resumable (a file that exists is not made again):
#   snap                     the FE rays O12, S, O1 (session rom3's three-ray basis), one FE process
#   basis NAME NPOD M        tools/rom_basis.py --turns --mixed: NPOD POD modes (0: every one),
#                            M pressure modes (0: rom_basis.py's --ptol 1e-3), their
#                            supremizers: n = NPOD + M (0 0: session rom3's b3, n 96, m 48)
#   ecsw NAME TOL...         the ECSW matrix of DATA/NAME/basis.h5 and one fit pass to the
#                            smallest TOL: DATA/NAME/weights_tol<TOL>.h5 for each
#   leg NAME TOL|none        crawlsim rom leg-file: DATA/NAME/leg_<TOL>.h5 (none: every element)
#   ecswtet NAME TOL...      the Tet10 set alone fitted further (rom_ecsw.py --set tet):
#                            DATA/NAME/wtet_tol<TOL>.h5
#   legmix NAME TTOL FTOL    the Tet10 weights of TTOL (wtet) with the fibres' of FTOL (weights),
#                            romsweep_combine_weights.py: DATA/NAME/leg_t<TTOL>_f<FTOL>.h5
#                            (TTOL, FTOL as Python's %g writes them: 0.001, 0.01)
# The timed run is run_romsweep_timed.sh.
# CS: the crawlsim binary (default build/tools/crawlsim).
set -euo pipefail
DATA=$1
stage=$2
shift 2
CS=${CS:-$PWD/build/tools/crawlsim}
EX=(--actuator leg --set S1=15 --set S2=15 --set S3=15)
export OMP_WAIT_POLICY=PASSIVE OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
mkdir -p "$DATA"
case $stage in
snap)
  nice -n 5 "$CS" rom snapshots --out "$DATA/snap" --mesh-size 8 --threads 1 "${EX[@]}" \
    --ray O12 --ray S --ray O1
  ;;
basis)
  name=$1 npod=$2 m=$3
  mkdir -p "$DATA/$name"
  [ -f "$DATA/$name/basis.h5" ] && exit 0
  args=(--turns --mixed --tol 1e-12) # session rom3's b3 with NPOD 0, M 0
  [ "$npod" != 0 ] && args+=(--n "$npod")
  [ "$m" != 0 ] && args+=(--m "$m")
  /usr/bin/time -f '== basis: %e s wall, %U s user' nice -n 5 /usr/bin/python3 \
    tools/rom_basis.py "$DATA/snap" "${args[@]}" --out "$DATA/$name/basis.h5" 2>&1 \
    | tee "$DATA/$name/basis.log"
  ;;
ecsw)
  name=$1
  shift
  D=$DATA/$name
  if [ ! -f "$D/ecsw_matrix.h5" ]; then
    /usr/bin/time -f '== ecsw-matrix: %e s wall, %U s user' nice -n 5 "$CS" rom ecsw-matrix \
      --basis "$D/basis.h5" --out "$D/ecsw_matrix.h5" --work "$D" "${EX[@]}" 2>&1 \
      | tee "$D/ecsw_matrix.log"
  fi
  T=()
  for t in "$@"; do T+=(--tol "$t"); done
  /usr/bin/time -f '== ecsw fit: %e s wall, %U s user' nice -n 5 /usr/bin/python3 \
    tools/rom_ecsw.py "$D/ecsw_matrix.h5" --out "$D/weights.h5" "${T[@]}" 2>&1 \
    | tee "$D/ecsw_fit.log"
  ;;
leg)
  name=$1 tol=$2
  D=$DATA/$name
  W=()
  # rom_ecsw.py names the files by the tolerance in Python's %g (3e-2: weights_tol0.03.h5)
  [ "$tol" != none ] && W=(--weights "$D/weights_tol$(printf '%g' "$tol").h5")
  [ -f "$D/leg_$tol.h5" ] && exit 0
  /usr/bin/time -f '== leg-file: %e s wall, %U s user' nice -n 5 "$CS" rom leg-file \
    --basis "$D/basis.h5" "${W[@]}" --out "$D/leg_$tol.h5" --work "$D" "${EX[@]}" 2>&1 \
    | tee "$D/leg_$tol.log"
  ;;
ecswtet)
  name=$1
  shift
  D=$DATA/$name
  T=()
  for t in "$@"; do T+=(--tol "$t"); done
  /usr/bin/time -f '== ecsw fit, Tet10s: %e s wall, %U s user' nice -n 5 /usr/bin/python3 \
    tools/rom_ecsw.py "$D/ecsw_matrix.h5" --set tet --out "$D/wtet.h5" "${T[@]}" 2>&1 \
    | tee "$D/ecsw_tet_fit.log"
  ;;
legmix)
  name=$1 tt=$2 tf=$3
  D=$DATA/$name
  W=$D/weights_t${tt}_f${tf}.h5
  /usr/bin/python3 "$(dirname "$0")/romsweep_combine_weights.py" "$D/wtet_tol$tt.h5" \
    "$D/weights_tol$tf.h5" "$W"
  /usr/bin/time -f '== leg-file: %e s wall, %U s user' nice -n 5 "$CS" rom leg-file \
    --basis "$D/basis.h5" --weights "$W" --out "$D/leg_t${tt}_f${tf}.h5" --work "$D" \
    "${EX[@]}" 2>&1 | tee "$D/leg_t${tt}_f${tf}.log"
  ;;
*)
  echo "run_romsweep.sh: unknown stage '$stage' (snap, basis, ecsw, leg, ecswtet, legmix)" >&2
  exit 1
  ;;
esac
