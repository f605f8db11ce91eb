#!/bin/sh
# usage: worker.sh: runs the jobs listed in $J (default /tmp/margin16/jobs; one "GAIT LEVEL [TEND]"
# a line, appended at will) through one.sh, each once (a lock directory per job in $J.lock);
# start two for two runs at a time; a worker stops when $J.stop exists.
cd "$(dirname "$0")"
J=${J:-/tmp/margin16/jobs}; mkdir -p "$J.lock"; touch "$J"
while [ ! -e "$J.stop" ]; do
  did=
  while read -r g l te; do
    [ -z "$g" ] && continue
    case $te in [a-z]*) s=./set.sh ;; *) s=./one.sh ;; esac
    if mkdir "$J.lock/${g}_$l${te:+_$te}" 2>/dev/null; then $s "$g" "$l" $te; did=1; break; fi
  done < "$J"
  [ -z "$did" ] && sleep 5
done
