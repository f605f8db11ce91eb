#!/bin/bash
# Merge the symmetric-mesh case files into a table, print the model's report under the three
# rules and draw the pictures. From the repository root, after a build:
#   bash docs/bench/calibration_cases_symmesh/finish.sh [CASES_DIR] [OUT_DIR]
# (defaults: the committed cases/, build/symmesh). Writes OUT_DIR/table.h5, report_RULE.txt,
# pred_RULE.h5 and tools/plot_calibration.py's pictures of the rbf-pair model.
set -euo pipefail
cases=${1:-docs/bench/calibration_cases_symmesh/cases}
out=${2:-build/symmesh}
mkdir -p "$out/cases"
cp "$cases"/*.h5 "$out/cases/"
for rule in prism rbf rbf-pair; do
  build/tools/crawlsim calibrate --actuator leg --p-max 0.4 --newton-rtol 1e-8 --mesh-symmetric 1 \
    --merge-only --dir "$out/cases" --out "$out/table.h5" --cal-rule "$rule" \
    --model-out "$out/pred_$rule.h5" > "$out/report_$rule.txt" 2>&1
done
/usr/bin/python3 tools/plot_calibration.py "$out/table.h5" --model "$out/pred_rbf-pair.h5" -o "$out"
grep -A3 "held out (never" "$out/report_rbf-pair.txt" | head -4
grep "every held-out case\|MISSES" "$out/report_rbf-pair.txt" || true
