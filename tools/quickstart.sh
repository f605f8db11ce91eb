#!/usr/bin/env bash
# The main job: install what is missing, build crawlsim, then the paper's flat road on the
# scene's defaults (strain legs on the FE calibration, the adaptive tree step, the designed gait
# gaits/flat_road_rod.csv, named for the model it was first designed on: gaits/README.md; the
# banner of each run says what ran)
#  1. under `paper` conditions (the paper's assumption: the legs' self-weight ignored), plotted
#     against Table 2: out/flat_road_paper.{h5,png}
#  2. under `earth` conditions (gravity on every body): the verdict, out/flat_road_earth.*
# a heat map of the gait (out/flat_road_gait.png) and the animation of the paper run
# (out/flat_road_paper.gif: side and top views, a frame every 0.1 s of simulated time, ~100
# frames, about 15 s of Python). Each run also writes an .xdmf beside its .h5 (ParaView:
# File > Open > out/flat_road_paper.xdmf). README, "Headline results".
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build build -j2
# the library, its header and the Python package under ~/.local (docs/reference/api.md,
# docs/reference/python.md): afterwards `/usr/bin/python3 -c "import crawlsim"` works, the
# package finding its library without LD_LIBRARY_PATH
cmake --install build --prefix "$HOME/.local" >/dev/null
echo "quickstart: installed libcrawlsim and the Python package crawlsim under $HOME/.local"
mkdir -p out

run() { # run the flat road; a run that stops (collapse, fall) still leaves a readable file
  local out=$1; shift
  if ./build/tools/crawlsim run --scene flat-road --out "out/$out.h5" "$@"; then
    echo "quickstart: $out: run completed"
  else
    echo "quickstart: $out: the run stopped early (message above); plotting what it wrote"
  fi
  /usr/bin/python3 tools/plot_track.py "out/$out.h5" -o "out/$out.png"
}
run flat_road_paper --conditions paper
run flat_road_earth --conditions earth
/usr/bin/python3 tools/plot_gait.py gaits/flat_road_rod.csv -o out/flat_road_gait.png
# the animation: 10 frames a second at 1 simulated second per second = a frame every 0.1 s
if /usr/bin/python3 tools/animate_run.py out/flat_road_paper.h5 -o out/flat_road_paper.gif \
    --fps 10 --speed 1; then
  echo "quickstart: results in out/ (HDF5, XDMF, PNG) and the animation out/flat_road_paper.gif"
else
  echo "quickstart: results in out/ (HDF5, XDMF, PNG); no animation (message above)"
fi
