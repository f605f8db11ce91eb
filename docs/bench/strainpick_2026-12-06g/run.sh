#!/bin/sh
# usage: run.sh RUN...  issue 33's must-show items on `--legs strain` at its defaults (links 2,
# 0.5 ms, backward Euler), one run after the other, nice 5, resumable (a run whose RUN.txt exists
# here is skipped). RUN = GROUP/CASE:
#   flat/CASE    crawlsim run --scene flat-road (paper, the shipped gait), scored by
#                docs/bench/flat16_2026-12-06e/xs.py
#   obst/CASE    crawlsim run --scene obstacle (paper, k3 + the landing gate as shipped), scored
#                by docs/bench/gate_2026-12-06f/score.py (T as gate_set.sh: nominal 35 s,
#                ramp0.5 47 s, the others 36 s)
#   earth/CASE   crawlsim run --scene flat-road --conditions earth (gaits/flat_road_earth.csv),
#                scored by tools/earth_track.py
#   paper/CASE   --gait gaits/flat_road_paper.csv, paper (tools/studies/paper_gait.study), xs.py
#   obst/earth   crawlsim run --scene obstacle --conditions earth --t-end 8
#   paper/earth  the paper's table under earth
# CASE: nominal ramp0.1 ramp0.5 mu0.6 mu1.0 m25g m75g tau0.5x tau2x dt_half (the strain step
# halved: --dt 0.00025) mu0; obst/dt1ms: the strain level's step before the sixth session
# (--dt 0.001).  LEGS=rod runs the same on the rod (the scene's elements; LINKS=N another
# number, files RUN_rodN.*); TEND=S ends every run of the call at S (files RUN_tS.*).
# The HDF5 files go to $OUT (default /work/rom_data/strainpick; not kept: each is regenerated
# by its line here, 20-150 CPU s); RUN.txt (GROUP_CASE.txt) holds the score, RUN.log the run's
# summary with `uptime` before it and CPU and wall time after it.
cd "$(dirname "$0")/../../.."
B=docs/bench/strainpick_2026-12-06g
OUT=${OUT:-/work/rom_data/strainpick}
LEGS=${LEGS:-strain}
mkdir -p "$OUT"
for r in "$@"; do
  g=${r%%/*}; n=${r#*/}
  T=; a=
  case $n in
    nominal) ;;
    ramp0.1) a="--ramp 0.1" ;;
    ramp0.5) a="--ramp 0.5" ;;
    mu0.6) a="--friction 0.6" ;;
    mu1.0) a="--friction 1.0" ;;
    m25g) a="--support-mass 0.025" ;;
    m75g) a="--support-mass 0.075" ;;
    tau0.5x) a="--tau 0.01" ;;
    tau2x) a="--tau 0.04" ;;
    dt_half) if [ "$LEGS" = strain ]; then a="--dt 0.00025"; else a="--dt 0.0005"; fi ;;
    mu0) a="--friction 0" ;;
    dt1ms) a="--dt 0.001" ;;
    earth) ;;
    *) echo "run.sh: unknown case $n" >&2; exit 2 ;;
  esac
  case $g in
    flat) s="--scene flat-road --conditions paper" ;;
    earth) s="--scene flat-road --conditions earth" ;;
    paper) s="--scene flat-road --gait gaits/flat_road_paper.csv --conditions paper --t-end 9" ;;
    obst) s="--scene obstacle --conditions paper"; T=36
          [ "$n" = nominal ] && T=35; [ "$n" = ramp0.5 ] && T=47 ;;
    *) echo "run.sh: unknown group $g" >&2; exit 2 ;;
  esac
  if [ "$n" = earth ]; then
    s=$(echo "$s" | sed 's/--conditions paper/--conditions earth/'); [ "$g" = obst ] && T=8
  fi
  [ -n "$TEND" ] && T=$TEND
  [ -n "$T" ] && s="$s --t-end $T"
  tag=${g}_${n}; [ "$LEGS" = strain ] || tag=${tag}_$LEGS$LINKS
  [ -n "$LINKS" ] && a="$a --links $LINKS"
  [ -n "$TEND" ] && tag=${tag}_t$TEND
  [ -s $B/$tag.txt ] && continue
  uptime > $B/$tag.log
  echo "crawlsim run $s $a --legs $LEGS" >> $B/$tag.log
  # shellcheck disable=SC2086
  /usr/bin/time -f "%U s user, %e s wall" nice -n 5 build/tools/crawlsim run $s $a \
    --legs $LEGS --out "$OUT/$tag.h5" >> $B/$tag.log 2>&1
  case $g in
    obst) /usr/bin/python3 docs/bench/gate_2026-12-06f/score.py "$OUT/$tag.h5" > $B/$tag.txt ;;
    earth) /usr/bin/python3 tools/earth_track.py "$OUT/$tag.h5" > $B/$tag.txt ;;
    *) /usr/bin/python3 docs/bench/flat16_2026-12-06e/xs.py "$OUT/$tag.h5" > $B/$tag.txt ;;
  esac
  rm -f "$OUT/$tag.xdmf"
done
