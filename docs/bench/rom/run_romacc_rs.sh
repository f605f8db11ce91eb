#!/usr/bin/env bash
# Session romacc: the sparse random training rays RS1-RS6 of the short leg (per segment a level,
# chambers vented at random: docs/notes/rom.md "Session romacc"), one FE process on one thread
# under nice 10, resumable (finished rays are skipped). Usage: run_romacc_rs.sh OUTDIR [CRAWLSIM]
set -e
OUT=${1:?OUTDIR}
CS=${2:-build/tools/crawlsim}
export OMP_WAIT_POLICY=PASSIVE
R=""
for r in RS1 RS2 RS3 RS4 RS5 RS6; do R="$R --ray $r"; done
exec nice -n 10 "$CS" rom snapshots --out "$OUT" --mesh-size 8 --threads 1 --actuator leg \
  --set S1=15 --set S2=15 --set S3=15 $R
