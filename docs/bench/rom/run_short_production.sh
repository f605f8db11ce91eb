#!/usr/bin/env bash
# The short leg's training production (docs/notes/rom.md, session rom2): the held-out rays'
# patterns first (single chambers, random per-segment rays, the mirrored S, Z), one FE process
# on one thread under nice 10, into build/rom_short (resumable: finished rays are skipped; run
# it again after a stop). From the repository root after a Release build.
cd "$(dirname "$0")/../../.."
export OMP_WAIT_POLICY=PASSIVE
R=""
for r in O12 S T_H4 T_S2 O1 O2 O3 O4 R1 Smirror R2 Z O13 R3 II1only II2only II3only Fx Fy Gx T_H7 T_R O1234 O124 O23 O34 O41 R4 R5 R6 Gy Gz Fzc Fzt O12Fc SGy O12O3r05 O1O234r05 T_O12GF; do R="$R --ray $r"; done
exec nice -n 10 build/tools/crawlsim rom snapshots --out build/rom_short --mesh-size 8 --threads 1 --actuator leg --set S1=15 --set S2=15 --set S3=15 $R
