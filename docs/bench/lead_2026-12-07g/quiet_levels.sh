#!/usr/bin/env bash
# fourteenth session: the default and the adaptive BDF2 rows, three quiet runs, rod 8x1 for the ratio
set -euo pipefail
# REF: a directory holding the rod-at-32-elements reference tracks (track-*-rod-l32-*), OUT: a scratch directory
: "${REF:?}" "${OUT:?}"
cd "$(git rev-parse --show-toplevel)"
cmake -S . -B "$OUT"/build -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null && cmake --build "$OUT"/build -j2 --target crawlsim >/dev/null
for r in 1 2 3; do
  mkdir -p "$OUT"/W$r "$OUT"/O$r
  cp "$REF"/track-*-rod-l32-* "$OUT"/W$r/
  uptime > "$OUT"/uptime_before_$r.txt
  /usr/bin/python3 tools/bench_levels.py --crawlsim "$OUT"/build/tools/crawlsim --tasks track --ref-links 32 --rod-configs 8x1 \
    --strain-configs 2@5e-3o1a2.5e-4,2@5e-3o2a5e-4 \
    --work "$OUT"/W$r --out-dir "$OUT"/O$r --table "$OUT"/O$r/levels.csv > "$OUT"/run$r.log 2>&1
  uptime > "$OUT"/uptime_after_$r.txt
done
echo done
