#!/usr/bin/env bash
# The main job: install what is missing, build crawlsim, run the paper's flat-road track with
# the shipped gait, and plot it. Writes out/flat_road.h5 and out/flat_road.png, and the same
# scene at 1 m/s^2 gravity (out/flat_road_g1.*), which shows the gait's mechanism without the
# legs folding under the robot's weight (README, "Flat road: results").
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build build -j2
mkdir -p out

run() { # run a scene; a run that stops (collapse, fall) still leaves a readable file
  local out=$1; shift
  if ./build/tools/crawlsim run --scene flat-road --out "out/$out.h5" "$@"; then
    echo "quickstart: $out: run completed"
  else
    echo "quickstart: $out: the run stopped early (message above); plotting what it wrote"
  fi
  /usr/bin/python3 tools/plot_track.py "out/$out.h5" -o "out/$out.png"
}
run flat_road
run flat_road_g1 --gravity 1
echo "quickstart: results in out/ (HDF5 + PNG)"
