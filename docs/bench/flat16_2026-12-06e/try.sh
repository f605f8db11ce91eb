#!/bin/sh
# One design of the search's family at the default 8 elements: the nominal and the ramp runs
# through tools/gait_search.py (resumable, DIR/results.csv), then the support-mass runs of the
# set (25 and 75 g, the set's most mass-sensitive members for these designs) with the design's
# table. usage (from the repository root): try.sh S,H,U,TL,E,O [TABLE_RAMP]
set -e
B=docs/bench/flat16_2026-12-06e
X0=${1:?S,H,U,TL,E,O}; R=${2:-0.3}
nice -n 5 /usr/bin/python3 tools/gait_search.py --dir $B/search --evals 1 --ramps 0.5,0.1 \
  --table-ramp "$R" --x0 "$X0" | head -1
k=$(/usr/bin/python3 -c "
import sys; sys.path.insert(0, 'tools'); import gait_search as g
g.TABLE_RAMP[0] = $R; print(g.key([float(v) for v in '$X0'.split(',')]))")
for m in 0.025 0.075; do
  f=$B/search/cases/d${k}__m${m}.h5
  [ -f "$f" ] || nice -n 5 build/tools/crawlsim run --scene flat-road --conditions paper \
    --gait $B/search/cases/d$k/gait.csv --support-mass $m --quiet --out "$f" > "${f%.h5}.log" 2>&1
done
/usr/bin/python3 $B/xs.py $B/search/cases/d$k.h5 $B/search/cases/d${k}__*.h5
