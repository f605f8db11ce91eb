#!/bin/bash
# the rom bend sweep with main's code (romfast0) and this branch's, back to back, after run.log's run
while pgrep -f run_romfast_sweep.sh > /dev/null; do sleep 5; done
export OMP_WAIT_POLICY=PASSIVE OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
B=/work/rom_data/rom3/b3/basis_mixed.h5; W=/work/rom_data/rom3/b3/weights_only1e-2.h5
for bin in /work/rom_data/romfast/crawlsim_romfast0 /work/rom_data/romfast/timed/crawlsim; do
  echo "== $bin: $(uptime)"
  /usr/bin/time -f "== $bin: %e s wall, %U s user" $bin bend --model rom --rom-basis $B --rom-weights $W --actuator leg --set S1=15 --set S2=15 --set S3=15 --chambers 1,2 --p-max 0.4 --p-step 0.05 --out /work/rom_data/romfast/timed/ba_$(basename $bin).h5 2>&1 | grep -v "^ "
done
echo "== end: $(uptime)"
