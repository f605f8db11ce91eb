#!/bin/sh
# crun.sh TAG ARGS...: one `crawlsim run ARGS --quiet --out $D/TAG.h5` (D default
# /work/rom_data/strdef; CRAWLSIM the binary, default $D/crawlsim_base, a copy of the worktree's
# build at the tolerance study's commit, so later builds do not change a queued run), nice 5;
# its output, CPU (/usr/bin/time) and uptime in logs/TAG.log beside this script. A run whose
# log has its verdict line (it ran to its end or fell) is skipped (resumable). From the
# worktree.
TAG=$1; shift
D=${D:-/work/rom_data/strdef}
C=${CRAWLSIM:-$D/crawlsim_base}
L=$(dirname "$0")/logs
mkdir -p "$L"
if [ -f "$L/$TAG.log" ] && grep '^verdict' "$L/$TAG.log" | grep -qv interrupted; then
  echo "$TAG done before"; exit 0
fi
{ uptime; echo "crawlsim run $* --quiet --out $D/$TAG.h5"
  /usr/bin/time -f "%U user %S sys %e wall" nice -n 5 "$C" run "$@" --quiet --out "$D/$TAG.h5"
  echo "rc $?"; uptime; } > "$L/$TAG.log" 2>&1
echo "$TAG $(grep '^rc ' "$L/$TAG.log" | tail -1)"
