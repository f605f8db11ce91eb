#!/usr/bin/env bash
# Session romflat2 (2026-12-06/07, seventh): the flat road on the real leg's rom legs in
# resumable pieces, by romflat's script with this session's folders (docs/notes/rom.md "The rom
# legs' settling under paper"). From the repository root after a Release build:
#   bash docs/bench/romflat2_2026-12-06g/run_romflat.sh [LEG] [DIR]
# DIR defaults to /work/rom_data/romflat2/run (the binary c284d0e in DIR/bin, the checkpoint
# DIR/rom_flat.ck), the log to this folder's rom_flat.log; LEG, T_END, EVERY as romflat's.
set -euo pipefail
LOG=${LOG:-$PWD/docs/bench/romflat2_2026-12-06g/rom_flat.log} \
  exec bash docs/bench/romflat_2026-12-06f/run_romflat.sh \
  "${1:-/work/rom_data/romcontact/b10/leg_tol1e-2.h5}" "${2:-/work/rom_data/romflat2/run}"
