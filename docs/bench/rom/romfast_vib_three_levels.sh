#!/bin/bash
# the reduced tangents at 0, 0.075 and 0.15 MPa only (the 0.4 MPa level's reduced statics is the
# slow one), this branch's binary, then rom_modes.py against the FE's first three levels
set -euo pipefail
cd REPO
b=$1
OUT=DATA/vib; SNAP=DATA3/snap_b34; MFE=DATA/modes/modes_fe.h5
CS=DATA/timed/crawlsim
export OMP_WAIT_POLICY=PASSIVE OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
while [ ! -f $OUT/$b/basis.h5 ]; do sleep 10; done
mkdir -p $OUT/$b/l3
/usr/bin/time -f '== rom modes: %e s wall, %U s user' $CS rom modes --rom-only --basis $OUT/$b/basis.h5 --out $OUT/$b/l3/modes_rom.h5 --work $OUT/$b/l3 --pressure 0 --pressure 0.075 --pressure 0.15 --actuator leg --set S1=15 --set S2=15 --set S3=15 > $OUT/$b/l3/modes_rom.log 2>&1
/usr/bin/python3 tools/rom_modes.py $OUT/$b/l3/modes_rom.h5 $SNAP $OUT/$b/basis.h5 --fe $MFE > $OUT/$b/l3/modes.log 2>&1
echo "== $b (3 levels): $(tail -1 $OUT/$b/l3/modes.log) ($(uptime))"
