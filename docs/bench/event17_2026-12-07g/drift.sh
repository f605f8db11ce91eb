#!/bin/bash
# drift.sh BIN: test_strain_driver's frictionless centre of mass on the adaptive step (2.5e-4 mm,
# 1 s of the gait) with the default's Newton passes (16), one linearised pass (EV17_PASSES=1),
# and one pass with the support's kinematic closure iterated on the legs' prepare linearisation
# (EV17_CLOSURE=20), and one pass with the legs' momentum residual carried (EV17_CARRY=1: the
# law at the end; 2: the step's linear contact force) (scratch, trace.patch). BIN: the scratch
# build's test_strain_driver.
BIN=$1
export CS_SOURCE_DIR=${CS_SOURCE_DIR:-/tmp/event17/src}
uptime
for v in "" "EV17_PASSES=1" "EV17_PASSES=1 EV17_CLOSURE=20" "EV17_PASSES=1 EV17_CARRY=1" "EV17_PASSES=1 EV17_CARRY=2"; do
  echo "== ${v:-default (16 passes)}"
  env $v nice -n 5 $BIN 2>&1 | grep "the adaptive step (2.5e-4"
done
uptime
