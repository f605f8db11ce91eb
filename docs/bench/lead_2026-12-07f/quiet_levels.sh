#!/usr/bin/env bash
# thirteenth session: the default and the adaptive BDF2 rows, three quiet runs, rod 8x1 for the ratio
set -euo pipefail
cd "$(dirname "$0")/../../.."
cmake -S . -B ${LV:-/tmp/lv13}/build -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null && cmake --build ${LV:-/tmp/lv13}/build -j2 --target crawlsim >/dev/null
for r in 1 2 3; do
  mkdir -p ${LV:-/tmp/lv13}/W$r ${LV:-/tmp/lv13}/O$r
  cp ${REF:?rod l32 reference tracks}/track-*-rod-l32-* ${LV:-/tmp/lv13}/W$r/
  uptime > ${LV:-/tmp/lv13}/uptime_before_$r.txt
  /usr/bin/python3 tools/bench_levels.py --crawlsim ${LV:-/tmp/lv13}/build/tools/crawlsim --tasks track --ref-links 32 --rod-configs 8x1 \
    --strain-configs 2@5e-3o1a2.5e-4,2@5e-3o2a5e-4 \
    --work ${LV:-/tmp/lv13}/W$r --out-dir ${LV:-/tmp/lv13}/O$r --table ${LV:-/tmp/lv13}/O$r/levels.csv > ${LV:-/tmp/lv13}/run$r.log 2>&1
  uptime > ${LV:-/tmp/lv13}/uptime_after_$r.txt
done
echo done
