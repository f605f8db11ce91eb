#!/usr/bin/env bash
# The real leg's (paper geometry, l_soft 8 mm, symmetric mesh: 12 952 Tet10, 70 233 dofs)
# training production for the reduced FE leg (docs/notes/rom.md, "The real leg's training"):
# the short leg's ray list without the rays that are quarter or half turns of others (O2-O4,
# O23, O34, O41, Smirror, Fy, Gy: tools/rom_basis.py --turns makes them on the symmetric mesh).
# One FE process on one thread under nice 5, into DIR (default build/rom_l8). Resumable:
# finished rays are kept, an interrupted one continues from its last step; run it again after
# a stop. From the repository root after a Release build.
set -euo pipefail
DIR=${1:-build/rom_l8}
export OMP_WAIT_POLICY=PASSIVE
R=()
for r in O12 S T_H4 T_S2 O1 R1 Z II1only R2 O13 Fx Gx O1O234r05 O12O3r05 O124 II2only II3only \
         R3 T_H7 T_R O1234 R4 R5 R6 Gz Fzc Fzt O12Fc SGy T_O12GF; do R+=(--ray "$r"); done
exec nice -n 5 build/tools/crawlsim rom snapshots --out "$DIR" --mesh-size 8 --threads 1 \
  --actuator leg "${R[@]}"
