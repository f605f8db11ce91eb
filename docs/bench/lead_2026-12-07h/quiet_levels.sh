#!/usr/bin/env bash
# fifteenth session: the default and the adaptive BDF2 rows, three quiet runs, rod 8x1 for the ratio
set -euo pipefail
cd /work/main
cmake -S . -B /work/lead/lv15/build -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null && cmake --build /work/lead/lv15/build -j2 --target crawlsim >/dev/null
for r in 1 2 3; do
  mkdir -p /work/lead/lv15/W$r /work/lead/lv15/O$r
  cp /work/lead/lv12/W/track-*-rod-l32-* /work/lead/lv15/W$r/
  uptime > /work/lead/lv15/uptime_before_$r.txt
  /usr/bin/python3 tools/bench_levels.py --crawlsim /work/lead/lv15/build/tools/crawlsim --tasks track --ref-links 32 --rod-configs 8x1 \
    --strain-configs 2@5e-3o1a2.5e-4,2@5e-3o2a5e-4 --no-whole \
    --work /work/lead/lv15/W$r --out-dir /work/lead/lv15/O$r --table /work/lead/lv15/O$r/levels.csv > /work/lead/lv15/run$r.log 2>&1
  uptime > /work/lead/lv15/uptime_after_$r.txt
done
echo done
