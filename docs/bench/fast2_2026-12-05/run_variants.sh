#!/bin/sh
# Passes per step of the 5 ms backward-Euler tree step on the flat road's first second under
# diagnostic switches. Needs a build with trace.patch applied (environment switches, NOT in the
# library): from the root, `git apply docs/bench/fast2_2026-12-05/trace.patch`, build
# bench_strain_driver, then run this from build/tests/core. Prints, per variant, the bench's
# passes line and passes.py's histogram (passes per try) and mean passes per 0.1 s window.
#   FAST2_MU=0         legs frictionless       FAST2_NOTERRAIN=1  legs without contact
#   FAST2_NOKEPT=1     no kept factor (condenseKept) at the iterates
#   FAST2_NOSECANT=1   no anchor secant        FAST2_CHC=0        no Hunt-Crossley damping
#   FAST2_ONSET=X      the law's d_onset (mm)  FAST2_DAMP3=1      damping from the 3rd pass
#   FAST2_PRED=1       a first iterate at the support's start twist (as BDF2's)
#   FAST2_LOSTKEEP=1   keep the factor where a slot only lost its touch
#   FAST2_NOMOMROWS=1  the base's linear rows stay prepare's velocity form (no momentumRows)
#   FAST2_TRACE=1      per pass: every leg's and the support's move (mm); FAST2_TRACE2=1 also
#                      every contact leg's [touching shapes, contact force's z, its x-y norm]
D=$(dirname "$0")
for v in "" "FAST2_NOKEPT=1" "FAST2_NOSECANT=1" "FAST2_MU=0" "FAST2_MU=0 FAST2_NOKEPT=1" \
         "FAST2_NOTERRAIN=1" "FAST2_CHC=0" "FAST2_ONSET=1e-5" "FAST2_ONSET=1e-2" \
         "FAST2_DAMP3=1" "FAST2_PRED=1" "FAST2_LOSTKEEP=1" "FAST2_NOMOMROWS=1" \
         "FAST2_NOMOMROWS=1 FAST2_NOTERRAIN=1"; do
  echo "== [$v]"
  env FAST2_TRACE=1 $v ./bench_strain_driver 1 strain:3:0.005:1 2>trace.tmp | grep -E "passes|stopped"
  python3 "$D/passes.py" trace.tmp
done
rm -f trace.tmp
