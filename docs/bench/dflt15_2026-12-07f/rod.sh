#!/bin/sh
# rod.sh: the converged reference on the obstacle past its first 4 s: the nodal rod at 32
# elements per segment, one macro step, 0.25 ms (the command of robot/levels.csv's obstacle
# reference, /work/lead/lv11a/W/track-obstacle-rod-l32-m1-dt0.00025-t4.json, to 10.5 s
# instead of 4: past legs C and G's landing on the step's top at ~9.05 s, where the default
# and BDF2 part). Log logs/rod32_obst10.log, run file $D/rod32_obst10.h5; resumable. Waits for
# the PID given (the batch) to end first, so no more than two runs share the machine.
[ -n "$1" ] && while kill -0 "$1" 2>/dev/null; do sleep 20; done
H=$(dirname "$0"); D=${D:-/tmp/dflt15/runs}; C=${CRAWLSIM:-/tmp/dflt15/crawlsim}
tag=rod32_obst10
if [ -f "$H/logs/$tag.log" ] && grep -q '^rc ' "$H/logs/$tag.log"; then exit 0; fi
{ uptime; echo "crawlsim run --scene obstacle --legs rod --links 32 --macro-steps 1 --dt 0.00025 --t-end 10.5 --out $D/$tag.h5"
  /usr/bin/time -f "%U user %S sys %e wall" nice -n 5 "$C" run --scene obstacle --legs rod --links 32 \
    --macro-steps 1 --dt 0.00025 --t-end 10.5 --out "$D/$tag.h5"
  echo "rc $?"; uptime; } > "$H/logs/$tag.log" 2>&1
rm -f "$D/$tag.xdmf"
