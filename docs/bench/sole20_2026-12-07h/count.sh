#!/bin/sh
# count.sh CRAWLSIM: how often the foot's law tangent (robot_strain_shape.c
# csr_strainShapeTangent_) takes contact_soft_jac.c's closed form (breakpoint 1, line 217: the
# call of csc_softShapeJacobian) and how often it differences the law (breakpoint 2, line 221:
# the 12-evaluation loop, reached only where the closed form declines or for a capsule), by gdb
# hit counts (count.gdb; the lines are those of commit f442602's robot_strain_shape.c) on the
# flat road's 9.5 s, the obstacle's first 4 s and `earth` (1.5 s). Out: stdout (gdbcount.log)
cd "$(dirname "$0")/../../.." || exit 1
for sc in "--scene flat-road" "--scene obstacle --t-end 4" \
  "--scene flat-road --gait gaits/flat_road_paper.csv --conditions earth --t-end 1.5"; do
  echo "== $sc"
  # shellcheck disable=SC2086
  nice -n 5 gdb -batch -x docs/bench/sole20_2026-12-07h/count.gdb --args "$1" run --legs strain $sc \
    --out /tmp/sole20/gdbrun.h5 2>&1 | grep -E "breakpoint already hit|^[0-9] +breakpoint"
done
