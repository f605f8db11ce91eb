#!/bin/sh
# obst13: the lead's set (docs/bench/lead_2026-12-07d/run.sh) with GAIT=NAME (gait NAME.csv, gate
# NAME.gate in $T, default /tmp/obst13; files CASE.log/.txt become NAME_CASE.*; no GAIT: the shipped
# gaits/obstacle.{csv,gate} as `crawlsim run --scene obstacle` takes them, files CASE.*), EXTRA
# (more flags), BIN (the binary, default build/tools/crawlsim).
# The lead's header follows.
# the lead's set (eleventh session): the obstacle's default as shipped after ramp11 (gaits/obstacle.{csv,gate}
# with the crawl statement), `crawlsim run --scene obstacle` with the case's flags and NO --t-end
# (the run ends where the gait is over on the table's clock, cs_runOverAt), one run after the
# other, nice 5, resumable (a case whose CASE.txt exists here is skipped).
# usage: run.sh CASE...   CASE: nominal ramp0.1 ramp0.5 mu0.6 mu1.0 m25g m75g tau0.5x tau2x dt_half
# (the set of issue 33, as docs/bench/obst10_2026-12-07c/run.sh names it)
# HDF5 files in $D (default /work/rom_data/lead11; not kept); CASE.log: uptime before and after,
# the command, the run's banner and summary, CPU (user) and wall; CASE.txt: Table 3's nodes
# (../gate_2026-12-06f/score.py), the lateral slots by the table's clock
# (../obstlat_2026-12-07b/lateral.py: it does not know the skip), the crawl's decision and the
# run's end (the run file's attributes).
cd "$(dirname "$0")/../../.."
B=docs/bench/obst13_2026-12-07e
D=${D:-/work/rom_data/obst13}
T=${T:-/tmp/obst13}
BIN=${BIN:-build/tools/crawlsim}
if [ -n "$GAIT" ]; then P=${GAIT}_${NOISE:+${NOISE}_}; G="--gait $T/$GAIT.csv --gate $T/$GAIT.gate --conditions paper"; GD=$T/$GAIT.gait; else P=${NOISE:+${NOISE}_}; G=; GD=gaits/obstacle.gait; fi
mkdir -p "$D"
cases='nominal| ramp0.1|--ramp 0.1 ramp0.5|--ramp 0.5
mu0.6|--friction 0.6 mu1.0|--friction 1.0 m25g|--support-mass 0.025
m75g|--support-mass 0.075 tau0.5x|--tau 0.01 tau2x|--tau 0.04
dt_half|--step-tol 1.25e-4'
for n in "$@"; do
  row=$(printf '%s\n' "$cases" | sed 's/ \([a-z0-9._]*|\)/\n\1/g' | grep "^$n|") ||
    { echo "run.sh: unknown case $n" >&2; exit 2; }
  a=$(echo "$row" | cut -d'|' -f2)
  o=$P$n
  [ -s $B/$o.txt ] && continue
  uptime > $B/$o.log
  echo "$BIN run --scene obstacle $G $a $EXTRA" >> $B/$o.log
  # shellcheck disable=SC2086
  /usr/bin/time -f "%U s user, %e s wall" nice -n 5 $BIN run --scene obstacle \
    $G $a $EXTRA --out "$D/$o.h5" >> $B/$o.log 2>&1
  uptime >> $B/$o.log
  { /usr/bin/python3 docs/bench/gate_2026-12-06f/score.py "$D/$o.h5"
    /usr/bin/python3 docs/bench/obstlat_2026-12-07b/lateral.py $GD "$D/$o.h5"
    /usr/bin/python3 -c "import h5py, sys; f = h5py.File(sys.argv[1], 'r'); print('crawl: ' + ', '.join('%s %s' % (k, f.attrs[k]) for k in ('crawl_skip_s', 'crawl_boundaries_read', 'crawl_z_mm', 'gate_held_s'))); u = lambda v: v.decode() if isinstance(v, bytes) else v; print('end: t %.4f s, %d rows, status %s; %s' % (f['/time'][-1], f['/time'].shape[0], u(f.attrs['status']), u(f.attrs['end_reason'])))" "$D/$o.h5"; } > $B/$o.txt 2>&1
  rm -f "$D/$o.xdmf"
done
