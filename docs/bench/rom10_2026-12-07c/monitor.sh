#!/bin/bash
# log the FE process's CPU seconds (utime+stime from /proc) every 20 s beside the production's
# last line: the per-ray CPU (usage: monitor.sh PID OUTLOG PRODUCTION_LOG)
pid=$1; out=$2; prod=$3
tck=$(getconf CLK_TCK)
while kill -0 "$pid" 2>/dev/null; do
  read -r -a f < /proc/$pid/stat
  echo "$(date -u +%H:%M:%S) cpu $(( (${f[13]} + ${f[14]}) / tck )) s load $(cut -d' ' -f1 /proc/loadavg) $(tail -1 "$prod" | cut -c1-80)" >> "$out"
  sleep 20
done
