#!/bin/sh
# more3.sh: does the strain level climb the obstacle on backward Euler's nearly converged
# track: the default step at 6.25e-5 and 3.125e-5 mm, the whole climb (be_{TOL}_climb; no
# --t-end, the gated run ends with its table), the two at once. Logs logs/TAG.log, run files
# $D/TAG.h5; resumable (one.sh).
H=$(dirname "$0"); D=${D:-/tmp/dflt15/runs}; C=${CRAWLSIM:-/tmp/dflt15/crawlsim}
. "$H/one.sh"
for tol in 6.25e-5 3.125e-5; do
  one be_${tol}_climb --scene obstacle --strain-step adaptive --step-tol $tol &
done
wait
