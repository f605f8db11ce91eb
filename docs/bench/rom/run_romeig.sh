#!/usr/bin/env bash
# Session romeig (docs/notes/rom.md, "Eigenfrequencies with the fibre field"): the first four
# eigenfrequencies of the short leg at levels of O12's pattern, the reduced model with and without
# the mixed fibre field and the FE's vibration modes of loaded states, against the FE's.
# Usage: run_romeig.sh SHORT LEG.h5 DIR "CONFIG ..." [CRAWLSIM]
#   SHORT: the short leg's rays (data/rom/short, or /work/rom_data/short); LEG.h5: any leg file of
#   that mesh, for the fibre elements (data/rom/short/README.md: two commands); DIR: the outputs.
#   CONFIG: base | f120 | f32s (no fibre basis; 120 global fibre modes; 32 split per segment),
#   each optionally followed by +vib (the FE's 8 lowest vibration modes at 0, 0.075 and 0.3 MPa:
#   0.15 MPa held out of the enrichment) or +vibf (the same, and the modes' fibre strain
#   increments at their levels added to the fibre basis: rom_basis.py --fibre-vib). Every
#   basis: romlock's training (15 rays and their quarter turns, 96 POD modes, 16 pressure modes
#   split at the connectors (48), supremizers).
# (rom check writes its mesh files into DIR/snap.)
# Environment: LEVELS (the reduced levels, some of the FE file's five; default "0 0.15"),
#   FD (the tangent's finite-difference directions per level, default 4), CHECK (rays for `rom
#   check` on each basis, default none).
# Cost in session romeig (2026-12-06, load 6-15 on two cores, CPU s): the FE step 117; a basis
# about 2 min of wall time; `rom modes --rom-only` at 0 and 0.15 MPa 61-107; `rom check --ray
# T_H4` 103. The session ran `"f120+vib f120 f120+vibf base+vib"`, then CHECK=T_H4 on f120+vibf,
# f32s+vibf, and LEVELS="0.075 0.3 0.4" on f120+vibf (DIR/f120 and DIR/base held romlock's
# b96_f120.h5 and b96_base.h5, which these options remake).
# Resumable: a finished step's file is kept. One heavy job at a time, nice 5.
set -euo pipefail
SRC=${1:?SHORT}; LEG=${2:?LEG.h5}; D=${3:?DIR}; CFGS=${4:?CONFIGS}
CS=${5:-$PWD/build/tools/crawlsim}
PY=/usr/bin/python3
TOOLS=$(cd "$(dirname "$0")/../../../tools" && pwd)
EX=(--actuator leg --set S1=15 --set S2=15 --set S3=15)
export OMP_WAIT_POLICY=PASSIVE OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
mkdir -p "$D/snap" "$D/snap_o12"
SRC=$(readlink -f "$SRC")
# romlock's 15 training rays and the held-out T_H4, T_S2, T_H7 (links: the same files)
for r in Fx Gx II1only II2only II3only O1 O12 O124 O12O3r05 O13 O1O234r05 R1 R2 S Z T_H4 T_S2 \
         T_H7 mesh; do
  ln -sf "$SRC/$r.h5" "$D/snap/"
done
ln -sf "$SRC/O12.h5" "$SRC/mesh.h5" "$D/snap_o12/"
# 1. the FE's statics and tangents at five levels of O12's pattern (the reduced side: O12's own
#    four-mode basis, cheap); 124 s of CPU in session romfast
if [ ! -f "$D/modes_fe.h5" ]; then
  [ -f "$D/b_o12.h5" ] || nice -n 5 $PY "$TOOLS/rom_basis.py" "$D/snap_o12" --n 4 \
    --out "$D/b_o12.h5" > "$D/b_o12_basis.log" 2>&1
  /usr/bin/time -f '== rom modes (FE): %e s wall, %U s user' nice -n 5 "$CS" rom modes \
    --basis "$D/b_o12.h5" --out "$D/modes_fe.h5.tmp" --work "$D" --pressure 0 --pressure 0.075 \
    --pressure 0.15 --pressure 0.3 --pressure 0.4 "${EX[@]}" > "$D/modes_fe.log" 2>&1
  mv "$D/modes_fe.h5.tmp" "$D/modes_fe.h5"
fi
LEV=()
for p in ${LEVELS:-0 0.15}; do LEV+=(--pressure "$p"); done
L=$(echo ${LEVELS:-0 0.15} | tr ' ' '_') # the levels name the reduced files
for c in $CFGS; do
  f=${c%%+*}
  A=(--turns --n 96 --m 16 --p-split 19,42 --mixed)
  case $f in
    base) ;;
    f*s) A+=(--fibre-modes "${f:1:-1}" --f-split 19,42 --fibres "$LEG") ;;
    f*) A+=(--fibre-modes "${f:1}" --fibres "$LEG") ;;
  esac
  if [ "$c" != "$f" ]; then
    A+=(--vib "$D/modes_fe.h5" --nvib 8 --vib-level 0 --vib-level 0.075 --vib-level 0.3)
  fi
  if [ "${c#*+}" = vibf ]; then
    A+=(--fibre-vib)
  fi
  B="$D/$c"
  mkdir -p "$B"
  if [ ! -f "$B/basis.h5" ]; then
    echo "== $c: rom_basis.py ${A[*]} ($(date -u +%T), load $(cut -d' ' -f1-3 /proc/loadavg))"
    nice -n 5 $PY "$TOOLS/rom_basis.py" "$D/snap" "${A[@]}" --out "$B/basis.h5.tmp" \
      > "$B/basis.log" 2>&1
    mv "$B/basis.h5.tmp" "$B/basis.h5"
  fi
  if [ ! -f "$B/modes_rom_$L.h5" ]; then
    echo "== $c: rom modes --rom-only ${LEV[*]} ($(date -u +%T)," \
      "load $(cut -d' ' -f1-3 /proc/loadavg))"
    /usr/bin/time -f '== rom modes: %e s wall, %U s user' nice -n 5 "$CS" rom modes --rom-only \
      --fd-check "${FD:-4}" --basis "$B/basis.h5" --out "$B/modes_rom_$L.h5.tmp" --work "$B" \
      "${LEV[@]}" "${EX[@]}" > "$B/modes_rom_$L.log" 2>&1
    mv "$B/modes_rom_$L.h5.tmp" "$B/modes_rom_$L.h5"
  fi
  nice -n 5 $PY "$TOOLS/rom_modes.py" "$B/modes_rom_$L.h5" "$D/snap" "$B/basis.h5" \
    --fe "$D/modes_fe.h5" > "$B/modes_$L.log" 2>&1
  echo "== $c: $(tail -1 "$B/modes_$L.log")"
  for r in ${CHECK:-}; do
    [ -f "$B/check_$r.log" ] && continue
    /usr/bin/time -f '== rom check: %e s wall, %U s user' nice -n 5 "$CS" rom check \
      --snapshots "$D/snap" --basis "$B/basis.h5" --ray "$r" "${EX[@]}" \
      > "$B/check_$r.log.tmp" 2>&1
    mv "$B/check_$r.log.tmp" "$B/check_$r.log"
    echo "== $c: check $r: $(grep 'crawlsim rom: ray' "$B/check_$r.log")"
  done
done
