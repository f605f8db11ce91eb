#!/usr/bin/env bash
# Session romfast (docs/notes/rom.md, goal 2): the eigenfrequencies of loaded states. The FE's
# tangents at 0, 0.075, 0.15, 0.3 and 0.4 MPa of O12's pattern come from one `crawlsim rom modes`
# run (MODES_FE, below); then for each enrichment (the FE's 8 lowest vibration modes at the listed
# levels) a mixed basis on the 34 training rays (48 POD modes, m = 48, as session rom3's b34n48),
# the reduced tangents at the same levels (--rom-only, every element kept) and rom_modes.py
# against the FE's. Arguments: SNAP (the short leg's production), OUT, MODES_FE. CS (environment)
# is the crawlsim binary. Resumable: a finished step's file is kept.
set -euo pipefail
SNAP=$1
OUT=$2
MFE=$3
CS=${CS:-$PWD/build/tools/crawlsim}
EX=(--actuator leg --set S1=15 --set S2=15 --set S3=15)
LEV=(--pressure 0 --pressure 0.075 --pressure 0.15 --pressure 0.3 --pressure 0.4)
export OMP_WAIT_POLICY=PASSIVE OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
mkdir -p "$OUT"
run() { # name, then the --vib-level options
  local b=$1
  shift
  if [ ! -f "$OUT/$b/basis.h5" ]; then
    mkdir -p "$OUT/$b"
    /usr/bin/python3 tools/rom_basis.py "$SNAP" --n 48 --m 48 --mixed --vib "$MFE" --nvib 8 "$@" \
      --out "$OUT/$b/basis.h5.tmp" > "$OUT/$b/basis.log" 2>&1
    mv "$OUT/$b/basis.h5.tmp" "$OUT/$b/basis.h5"
  fi
  if [ ! -f "$OUT/$b/modes_rom.h5" ]; then
    /usr/bin/time -f '== rom modes: %e s wall, %U s user' "$CS" rom modes --rom-only \
      --basis "$OUT/$b/basis.h5" --out "$OUT/$b/modes_rom.h5.tmp" --work "$OUT/$b" "${LEV[@]}" \
      "${EX[@]}" > "$OUT/$b/modes_rom.log" 2>&1
    mv "$OUT/$b/modes_rom.h5.tmp" "$OUT/$b/modes_rom.h5"
  fi
  /usr/bin/python3 tools/rom_modes.py "$OUT/$b/modes_rom.h5" "$SNAP" "$OUT/$b/basis.h5" \
    --fe "$MFE" > "$OUT/$b/modes.log" 2>&1
  echo "== $b: $(tail -1 "$OUT/$b/modes.log") ($(uptime))"
}
run vib0 --vib-level 0
run vib0_075_03 --vib-level 0 --vib-level 0.075 --vib-level 0.3
run vib0_015_04 --vib-level 0 --vib-level 0.15 --vib-level 0.4
