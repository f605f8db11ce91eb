#!/bin/sh
# noise.sh TOL: the pneumatic half of the adaptive step's noise floor: bench_strain_driver (its
# model is `crawlsim run`'s scene defaults under `paper`; the gate's waits are not modelled, and
# no gate waits in these runs) at the adaptive step TOL mm, longest step 5 ms, 2 modes, sub 4,
# with the pneumatics' CVODE tolerances as shipped (P1) and 10x tighter (P0.1), on the obstacle
# to 8 s and the flat road to 9.5 s; tracks into /work/rom_data/strdef/bench_pK. One run at a
# time, nice 5; from the worktree after a build. BENCH: the binary (default a copy made when
# the study ran, /work/rom_data/strdef/bench_strain_driver).
TOL=${1:-5e-4}
D=/work/rom_data/strdef
B=${BENCH:-$D/bench_strain_driver}
L=$(dirname "$0")/logs
for sc in obstacle:8 flat-road:9.5; do
  S=${sc%%:*}; T=${sc##*:}
  for p in 1 0.1; do
    mkdir -p $D/bench_p$p/$TOL
    { uptime; CS_SOURCE_DIR=$PWD CS_BENCH_SCENE=$S CS_BENCH_ADA=$TOL CS_BENCH_PTOL=$p \
      CS_BENCH_KEEP=$D/bench_p$p/$TOL nice -n 5 $B $T strain:2:0.005:1:0:-1:-1:-1:-1:-2:-1:4;
      uptime; } > $L/noise_${S}_${TOL}_p$p.log 2>&1
    echo "$S $TOL p$p rc $?"
  done
done
