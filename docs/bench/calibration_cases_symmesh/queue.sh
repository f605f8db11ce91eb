#!/bin/bash
# the FE calibration on the symmetric mesh: one stream, these cases in order, one thread
for c in "$@"; do
  OMP_NUM_THREADS=1 OMP_WAIT_POLICY=PASSIVE ./crawlsim calibrate --actuator leg --p-max 0.4 --newton-rtol 1e-8 --mesh-symmetric 1 --dir /work/runs/symmesh/cases --case $c --out /work/runs/symmesh/stream_$$.h5 > $c.log 2>&1
done
