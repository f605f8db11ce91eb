#!/bin/sh
# crun.sh TAG ARGS...: one `crawlsim run ARGS --quiet --out $D/TAG.h5` (D default
# /work/rom_data/adastep; CRAWLSIM the binary, default the worktree's build), its output, its
# CPU (/usr/bin/time) and uptime lines in $D/TAG.log; from the worktree.
TAG=$1; shift
D=${D:-/work/rom_data/adastep}
C=${CRAWLSIM:-./build/tools/crawlsim}
{ uptime; /usr/bin/time -f "%U user %S sys %e wall" nice -n 5 "$C" run "$@" --quiet --out "$D/$TAG.h5"; uptime; } > "$D/$TAG.log" 2>&1
echo "$TAG rc $?"
