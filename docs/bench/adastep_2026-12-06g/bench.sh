#!/bin/sh
# bench.sh: the levels bench's track task for the fixed 0.5 ms step and the adaptive step
# (tolerance 5e-4 and 1e-3 mm, 5 ms longest) on the flat road (9.5 s) and the obstacle's first
# 4 s, against the rod at 32 elements and 0.25 ms (the references copied from
# /work/rom_data/levels_ref into the work folder, whose JSON then point at the copies); one
# process at a time, fixed and adaptive one after the other per scene (interleaved). From the
# worktree after a build; W the work folder (default /work/rom_data/adastep/work).
W=${W:-/work/rom_data/adastep/work}
O=${O:-docs/bench/adastep_2026-12-06g}
uptime
nice -n 5 /usr/bin/python3 tools/bench_levels.py --tasks track --ref-links 32 --rod-configs "" \
  --strain-configs "${CONFIGS:-2@5e-4o1,2@5e-3o1a5e-4,2@5e-3o1a1e-3}" --work "$W" \
  --out-dir "$O" --table "$O/levels_fixed.csv"
uptime
