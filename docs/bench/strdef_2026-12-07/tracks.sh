#!/bin/sh
# tracks.sh: tracks.txt from the runs (cmp.py's whole-second |(dx, dz)| and steps.py's counts);
# from the worktree. A missing file is skipped.
H=docs/bench/strdef_2026-12-07
R=/work/rom_data/strdef
P="/usr/bin/python3 docs/bench/strainacc_2026-12-06f/cmp.py"
ex() { for f in "$@"; do [ -f "$f" ] && echo "$f"; done; }
OB=$(ex $R/obst_a1e-3.h5 $R/obst_a5e-4.h5 $R/obst_a2.5e-4.h5 $R/obst_a2e-4.h5 $R/obst_a1.25e-4.h5 $R/obst_a1e-4.h5 $R/obst_f0.5ms.h5 $R/obst_f0.25ms.h5)
FL=$(ex $R/flat_a1e-3.h5 $R/flat_a5e-4.h5 $R/flat_a2.5e-4.h5 $R/flat_a2e-4.h5 $R/flat_a1.25e-4.h5 $R/flat_a1e-4.h5 $R/flat_f0.5ms.h5 $R/flat_f0.25ms.h5)
echo "# obstacle 0-8 s against the rod at 32 elements and 0.25 ms (obst_rod32, this study)"
$P $R/obst_rod32.h5 $OB
echo "# the rod reference 0-8 s against levels_ref's 0-4 s (the same command to 4 s)"
$P /work/rom_data/levels_ref/track-obstacle-rod-l32-m1-dt0.00025-t4.h5 $R/obst_rod32.h5
# halves SC: each tolerance of scene SC (obst, flat) against its half
halves() {
  for pr in 1e-3:5e-4 5e-4:2.5e-4 2.5e-4:1.25e-4 2e-4:1e-4; do
    a=${pr%%:*}; b=${pr##*:}
    [ -f $R/$1_a$a.h5 ] && [ -f $R/$1_a$b.h5 ] && $P $R/$1_a$b.h5 $R/$1_a$a.h5
  done
}
echo "# obstacle: each tolerance against its half (1e-3/5e-4, 5e-4/2.5e-4, 2.5e-4/1.25e-4, 2e-4/1e-4)"
halves obst
echo "# obstacle: the fixed 0.5 ms against 0.25 ms"
ex $R/obst_f0.25ms.h5 > /dev/null && $P $R/obst_f0.25ms.h5 $(ex $R/obst_f0.5ms.h5)
echo "# flat road 9.5 s against the rod at 32 elements and 0.25 ms (levels_ref)"
$P /work/rom_data/levels_ref/track-flat-road-rod-l32-m1-dt0.00025.h5 $FL
echo "# flat road: each tolerance against its half"
halves flat
echo "# noise floor, the longest step ±10 % (1/220 s, 1/180 s; output every 0.05 s) against 5 ms"
for sc in obst flat; do for t in 5e-4 2.5e-4; do
  H2=$(ex $R/${sc}_a${t}_H220.h5 $R/${sc}_a${t}_H180.h5)
  [ -n "$H2" ] && $P $R/${sc}_a$t.h5 $H2
done; done
echo "# noise floor, the pneumatics' tolerances 10x tighter (bench_strain_driver, 5e-4, sub 4)"
M="/usr/bin/python3 $H/maxdiff.py"
for d in $R/bench_p0.1/5e-4/*.h5; do
  [ -f "$d" ] && $M $R/bench_p1/5e-4/$(basename $d) $d
done
echo "# the bench's run (P 1) against crawlsim run's (the same configuration)"
for d in $R/bench_p1/5e-4/*.h5; do
  case $d in *obstacle*) $M $R/obst_a5e-4.h5 $d;; *flat*) $M $R/flat_a5e-4.h5 $d;; esac
done
echo "# Magnus sub-intervals 2 (the new default) against 4, the same tolerance"
for sc in obst flat; do for t in 5e-4 2.5e-4; do
  [ -f $R/${sc}_a${t}_sub2.h5 ] && $P $R/${sc}_a$t.h5 $R/${sc}_a${t}_sub2.h5
done; done
echo "# sub 2 against the rod at 32 elements"
$P $R/obst_rod32.h5 $(ex $R/obst_a5e-4_sub2.h5 $R/obst_a2.5e-4_sub2.h5)
$P /work/rom_data/levels_ref/track-flat-road-rod-l32-m1-dt0.00025.h5 $(ex $R/flat_a5e-4_sub2.h5 $R/flat_a2.5e-4_sub2.h5)
echo "# the new build at sub 4 (the adaptive step by default, --step-tol 5e-4) against the study's binary"
[ -f $R/obst_a5e-4_sub4new.h5 ] && $P $R/obst_a5e-4.h5 $R/obst_a5e-4_sub4new.h5
echo "# B's landing at the step's edge (support x, tilt, B's foot x, height, normal force)"
/usr/bin/python3 docs/bench/strainpick_2026-12-06g/landing.py $R/obst_rod32.h5 $OB $(ex $R/obst_a2.5e-4_sub2.h5 $R/obst_a5e-4_sub2.h5) | grep -E "h5|5.30|5.40|5.60"
echo "# counts and CPU (steps = macro steps with the 0.3 s settling)"
/usr/bin/python3 $H/steps.py $R/obst_*.h5 $R/flat_*.h5
echo "# the defaults as a user runs them (crawlsim_def: no step flag): the obstacle's climb against the sub-2 run at 2.5e-4 to 8 s"
[ -f $R/def_obst.h5 ] && /usr/bin/python3 $H/maxdiff.py $R/obst_a2.5e-4_sub2.h5 $R/def_obst.h5
echo "# the paper's table (paper, 9 s) at the defaults against branch strainacc's rods at 16 elements (0.25 ms) and 32 (0.5 ms)"
for ref in /work/rom_data/strainacc/p_rod16_025ms.h5 /work/rom_data/strainacc/p_rod32_05ms.h5; do
  [ -f $R/def_paper.h5 ] && $P $ref $R/def_paper.h5
done
/usr/bin/python3 $H/steps.py $(ex $R/def_earth.h5 $R/def_obst.h5 $R/def_paper.h5)
echo "# the whole climb at the defaults against Table 3 (score.py of docs/bench/gate_2026-12-06f/)"
[ -f $R/def_obst.h5 ] && /usr/bin/python3 docs/bench/gate_2026-12-06f/score.py $R/def_obst.h5
