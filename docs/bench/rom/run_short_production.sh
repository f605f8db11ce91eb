#!/usr/bin/env bash
# The short leg's training production (docs/notes/rom.md, session rom2): the held-out rays'
# patterns first (a single chamber, random per-segment rays, Z; the rays that are quarter or
# half turns of others, O2-O4, O23-O41, Smirror, Fy, Gy, last: tools/rom_basis.py --turns
# makes them from O1, O12, S, Fx, Gx on the symmetric mesh), one FE process
# on one thread under nice (NICE, default 10), into OUTDIR (default build/rom_short; resumable:
# finished rays are skipped; run it again after a stop). From the repository root after a
# Release build. Usage: run_short_production.sh [OUTDIR [CRAWLSIM]]
cd "$(dirname "$0")/../../.."
OUT=${1:-build/rom_short}
CS=${2:-build/tools/crawlsim}
export OMP_WAIT_POLICY=PASSIVE
R=""
for r in O12 S T_H4 T_S2 O1 R1 Z II1only R2 O13 Fx Gx O1O234r05 O12O3r05 O124 II2only II3only R3 T_H7 T_R O1234 R4 R5 R6 Gz Fzc Fzt O12Fc SGy T_O12GF O2 O3 O4 O23 O34 O41 Smirror Fy Gy; do R="$R --ray $r"; done
exec nice -n "${NICE:-10}" "$CS" rom snapshots --out "$OUT" --mesh-size 8 --threads 1 --actuator leg --set S1=15 --set S2=15 --set S3=15 $R
