#!/usr/bin/env bash
# Session romlock (docs/notes/rom.md, "Locking (branch romlock)"): the same displacement and
# pressure bases with and without the mixed fibre field, on the held-out rays, every element
# kept. Usage: run_romlock.sh SNAPDIR LEG.h5 OUTDIR N "CONFIG ..." [CRAWLSIM]
#   N: POD modes (rom_basis.py --n); CONFIG: base (16 pressure modes split at the connectors,
#   as session romacc) or fN (base + N global fibre strain modes) or fNs (N split per segment).
# Environment: RAYS (default "T_H4 T_S2"), EXTRA (more rom_basis.py options, e.g. --turns).
# One reduced check at a time, nice 5.
set -e
SNAP=${1:?SNAPDIR}; LEG=${2:?LEG.h5}; OUT=${3:?OUTDIR}; N=${4:?N}; CFGS=${5:?CONFIGS}
CS=${6:-build/tools/crawlsim}
PY=/usr/bin/python3
TOOLS=$(cd "$(dirname "$0")/../../../tools" && pwd)
mkdir -p "$OUT/snap"
# the rays finished now, frozen (links), so that every configuration trains on the same ones
# while a production goes on writing into SNAPDIR
for f in "$SNAP"/*.h5; do ln -sf "$(readlink -f "$f")" "$OUT/snap/"; done
SNAP="$OUT/snap"
echo "rays: $(cd "$SNAP" && ls *.h5 | grep -v mesh.h5 | sed 's/.h5$//' | tr '\n' ' ')"
R=""; for r in ${RAYS:-T_H4 T_S2}; do R="$R --ray $r"; done
for c in $CFGS; do
  B="$OUT/b${N}_$c.h5"
  A="--n $N --m 16 --p-split 19,42 --mixed $EXTRA"
  case $c in
    base) ;;
    f*s) A="$A --fibre-modes ${c:1:-1} --f-split 19,42 --fibres $LEG" ;;
    f*) A="$A --fibre-modes ${c:1} --fibres $LEG" ;;
  esac
  echo "== $c: rom_basis.py $A ($(date -u +%H:%M:%S), load $(cut -d' ' -f1-3 /proc/loadavg))"
  nice -n 5 $PY "$TOOLS/rom_basis.py" "$SNAP" --out "$B" $A > "$OUT/b${N}_${c}_basis.log" 2>&1
  grep -E "^rom_basis: (mixed|fibres|n =)" "$OUT/b${N}_${c}_basis.log"
  /usr/bin/time -f "   %U s user, %e s wall" nice -n 5 "$CS" rom check --snapshots "$SNAP" --basis "$B" $R \
    --actuator leg --set S1=15 --set S2=15 --set S3=15 2>&1 | tee "$OUT/b${N}_${c}_check.log" | \
    grep -E "crawlsim rom: ray|t 1.000|user"
done
