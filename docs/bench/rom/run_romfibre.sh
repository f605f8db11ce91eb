#!/usr/bin/env bash
# Session romfibre (docs/notes/rom.md, "The fibre field hyper-reduced and in leg files"): the
# ECSW fit of the mixed fibre field on romlock's T_H4-meeting basis (b96_f120: 15 rays and their
# quarter turns, n = 144, m = 48, mf = 120), the held-out check with the weights, and the leg
# file that carries the fibre basis.
# Usage: run_romfibre.sh DIR [CRAWLSIM]
#   DIR holds b96_f120.h5 (romlock's, docs/bench/rom/romlock_b96_f120_basis.log says how it was
#   made) and short/ (the short leg's finished rays, data/rom/short: gunzip'd copies are fine).
# One heavy job at a time, nice 5.
set -e
D=${1:?DIR}; CS=${2:-build/tools/crawlsim}
PY=/usr/bin/python3
TOOLS=$(cd "$(dirname "$0")/../../../tools" && pwd)
LEG="--actuator leg --set S1=15 --set S2=15 --set S3=15"
cd "$D"
# 1. the leg file of the every-element model (set-up once: gmsh and the chambers' cubic forms)
[ -f leg_f120_all.h5 ] || nice -n 5 "$CS" rom leg-file --basis b96_f120.h5 --out leg_f120_all.h5 --work . $LEG
# 2. the fibres' ECSW rows at every 27th training state (9 of 240: FE states and turns), fitted
#    without G's 7 260 entries (--no-projection: G's action at the states is in the rows)
[ -f ecsw_f27.h5 ] || nice -n 5 "$CS" rom ecsw-matrix --basis b96_f120.h5 --out ecsw_f27.h5 --work . --stride 27 --only fibre $LEG
# (the session ran 3e-2 and 1e-1 as two passes; one pass records both, as separate runs would)
nice -n 5 $PY "$TOOLS/rom_ecsw.py" ecsw_f27.h5 --out wf.h5 --no-projection --tol 1e-1 --tol 3e-2
# 3. the held-out rays: every element (T_H4: the leg file against romlock's basis-file check),
#    the fibre weights at 3e-2 (T_H4, T_S2, T_H7) and at 1e-1 (T_H4); every Tet10 kept
C="nice -n 5 $CS rom check --snapshots short --leg-file leg_f120_all.h5 $LEG"
$C --ray T_H4 > check_all_T_H4.log 2>&1
$C --weights wf_tol0.03.h5 --ray T_H4 --ray T_S2 --ray T_H7 > check_wf3e-2.log 2>&1
$C --weights wf_tol0.1.h5 --ray T_H4 > check_wf1e-1_T_H4.log 2>&1
