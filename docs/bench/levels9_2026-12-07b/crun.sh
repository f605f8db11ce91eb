#!/bin/sh
# crun.sh TAG ARGS...: one `crawlsim run ARGS --quiet --out $D/TAG.h5` (D default
# /work/rom_data/levels9/runs; CRAWLSIM the binary, default /work/rom_data/levels9/crawlsim_main,
# a copy of main's build at 6ad0402: no C change to 1ebeda1, this branch's base), nice 5; its
# output, CPU (/usr/bin/time) and uptime in $LOGS/TAG.log (default logs/ beside this script).
# A run whose log has its rc line is skipped (resumable; a run that falls exits 1 and is a
# result too). From the worktree.
TAG=$1; shift
D=${D:-/work/rom_data/levels9/runs}
C=${CRAWLSIM:-/work/rom_data/levels9/crawlsim_main}
L=${LOGS:-$(dirname "$0")/logs}
mkdir -p "$L" "$D"
if [ -f "$L/$TAG.log" ] && grep -q '^rc ' "$L/$TAG.log"; then
  echo "$TAG done before"; exit 0
fi
{ uptime; echo "crawlsim run $* --quiet --out $D/$TAG.h5"
  /usr/bin/time -f "%U user %S sys %e wall" nice -n 5 "$C" run "$@" --quiet --out "$D/$TAG.h5"
  echo "rc $?"; uptime; } > "$L/$TAG.log" 2>&1
echo "$TAG $(grep '^rc ' "$L/$TAG.log" | tail -1)"
