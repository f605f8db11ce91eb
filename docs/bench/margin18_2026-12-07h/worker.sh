#!/bin/sh
# usage: worker.sh: runs the jobs listed in /tmp/margin18/jobs ("GAIT LEVEL CASE" a line,
# appended at will) through run.sh, each once (a lock directory per job); start two for two
# runs at a time; a worker stops when /tmp/margin18/jobs.stop exists.
cd "$(dirname "$0")"
J=/tmp/margin18/jobs; mkdir -p "$J.lock"; touch "$J"
while [ ! -e "$J.stop" ]; do
  did=
  while read -r g l c; do
    [ -z "$g" ] && continue
    if mkdir "$J.lock/${g}_${l}_$c" 2>/dev/null; then sh ./run.sh "$g" "$l" "$c"; did=1; break; fi
  done < "$J"
  [ -z "$did" ] && sleep 5
done
