#!/bin/sh
# tracks.sh: tracks.txt from the runs of bench.sh and runs.sh (cmp.py's whole-second errors and
# the run files' step counts); from the worktree
H=docs/bench/adastep_2026-12-06g
R=/work/rom_data/adastep
W=$R/work
S=/work/rom_data/strainacc
P="/usr/bin/python3 docs/bench/strainacc_2026-12-06f/cmp.py"
FF="$W/track-flat-road-strain-l2-m1-dt0.0005-o1.h5 $R/ada_flat_t0.0003.h5 $W/track-flat-road-strain-l2-m1-dt0.005-o1-a0.0005.h5 $W/track-flat-road-strain-l2-m1-dt0.005-o1-a0.001.h5 $R/ada_flat_t0.01.h5"
OO="$W/track-obstacle-strain-l2-m1-dt0.0005-o1-t4.h5 $R/ada_obst_t0.0003.h5 $W/track-obstacle-strain-l2-m1-dt0.005-o1-a0.0005-t4.h5 $W/track-obstacle-strain-l2-m1-dt0.005-o1-a0.001-t4.h5 $R/ada_obst_t0.003.h5 $R/ada_obst_t0.01.h5"
echo "# flat road 9.5 s: max |(dx, dz)| at whole seconds against the rod at 32 elements and 0.25 ms (levels_ref)"
$P $W/track-flat-road-rod-l32-m1-dt0.00025.h5 $FF
echo "# the same against the strain level's fixed 0.5 ms"
$P $FF
echo "# obstacle 4 s against the rod at 32 elements and 0.25 ms"
$P $W/track-obstacle-rod-l32-m1-dt0.00025-t4.h5 $OO
echo "# the same against the strain level's fixed 0.5 ms"
$P $OO
echo "# the paper's table (paper, 9 s) against the rod at 16 elements (0.25 ms), at 32 (0.5 ms) (branch strainacc's runs), and the strain level's fixed 0.5 ms"
for ref in $S/p_rod16_025ms.h5 $S/p_rod32_05ms.h5 $R/fix_paper_05ms.h5; do
  $P $ref $R/fix_paper_05ms.h5 $R/ada_paper.h5
done
echo "# step counts (run-file attributes: steps = macro steps incl. the 0.3 s settling; rejected_steps = the stages' rejections; adaptive_* the adaptive step's)"
for f in $R/ada_*.h5 $W/*strain*.h5 $R/fix_*.h5; do
  /usr/bin/python3 -c "
import h5py, os
f = h5py.File('$f', 'r')
a = {k: round(float(f.attrs[k]), 6) for k in f.attrs if 'adaptive' in k or 'steps' in k}
print(os.path.basename('$f'), a, f.attrs['status'].decode() if isinstance(f.attrs['status'], bytes) else f.attrs['status'])"
done
