#!/bin/sh
# more2.sh: does backward Euler's track, as its tolerance shrinks toward BDF2's (events.txt part
# 2), also put legs C and G on the step's edge at ~9.05 s: the default step at 6.25e-5 and
# 3.125e-5 mm on the obstacle to 12 s (be_{TOL}_o12), one after the other beside more.sh's rod
# (two runs at a time). Logs logs/TAG.log, run files $D/TAG.h5; resumable.
H=$(dirname "$0"); D=${D:-/tmp/dflt15/runs}; C=${CRAWLSIM:-/tmp/dflt15/crawlsim}
for tol in 6.25e-5 3.125e-5; do
  tag=be_${tol}_o12
  if [ -f "$H/logs/$tag.log" ] && grep -q '^rc ' "$H/logs/$tag.log"; then continue; fi
  { uptime; echo "crawlsim run --scene obstacle --strain-step adaptive --step-tol $tol --t-end 12 --out $D/$tag.h5"
    /usr/bin/time -f "%U user %S sys %e wall" nice -n 5 "$C" run --scene obstacle --strain-step adaptive \
      --step-tol $tol --t-end 12 --out "$D/$tag.h5"
    echo "rc $?"; uptime; } > "$H/logs/$tag.log" 2>&1
  rm -f "$D/$tag.xdmf"
done
