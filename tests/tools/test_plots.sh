#!/usr/bin/env bash
# test_plots.sh: smoke test of tools/plot_track.py, tools/plot_bend.py, tools/plot_gait.py and
# tools/plot_calibration.py, tools/stance_slip.py and tools/rod_vs_fe.py (argument 1: the
# crawlsim binary, which rod_vs_fe.py runs), tools/bench_levels.py --plot-only, and that
# tools/gait_search.py and tools/earth_gait.py reproduce the shipped gait descriptions.
# Writes small synthetic run/bend files (tests/tools/make_synthetic_h5.py, h5py) in a temp dir,
# runs both scripts, checks the PNGs exist and are non-empty PNGs, and checks that a missing
# file or dataset gives exit status 1 with a one-line message.
# Uses Debian's /usr/bin/python3 (python3-matplotlib, python3-h5py); override with $CS_PYTHON.
# Prints "N passed, N failed" last; exits non-zero on any failure.
set -u

HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
PY="${CS_PYTHON:-/usr/bin/python3}"
TRACK="$ROOT/tools/plot_track.py"
BEND="$ROOT/tools/plot_bend.py"
GAITMAP="$ROOT/tools/plot_gait.py"
SLIP="$ROOT/tools/stance_slip.py"
CALIB="$ROOT/tools/plot_calibration.py"
RODFE="$ROOT/tools/rod_vs_fe.py"
EXE="${1:-$ROOT/build/tools/crawlsim}"
GEN="$HERE/make_synthetic_h5.py"

TMP="$(mktemp -d "${TMPDIR:-/tmp}/cs_test_plots.XXXXXX")"
trap 'rm -rf "$TMP"' EXIT
export MPLBACKEND=Agg MPLCONFIGDIR="$TMP/mpl"

pass=0
fail=0
ok()  { pass=$((pass + 1)); echo "ok   $1"; }
bad() { fail=$((fail + 1)); echo "FAIL $1"; [ -n "${2:-}" ] && sed 's/^/     | /' "$2"; }

# expect_png NAME PNG CMD...: CMD exits 0 and writes a non-empty PNG
expect_png() {
  local name="$1" png="$2"; shift 2
  rm -f "$png"
  if ! "$@" >"$TMP/out.txt" 2>&1; then bad "$name (exit $?)" "$TMP/out.txt"; return; fi
  if [ ! -s "$png" ]; then bad "$name (no PNG or empty: $png)" "$TMP/out.txt"; return; fi
  if [ "$(head -c 8 "$png" | od -An -tx1 | tr -d ' \n')" != "89504e470d0a1a0a" ]; then
    bad "$name (not a PNG: $png)"; return
  fi
  ok "$name ($(wc -c <"$png") bytes)"
}

# expect_fail1 NAME PATTERN CMD...: CMD exits 1, stderr is one line matching PATTERN, no traceback
expect_fail1() {
  local name="$1" pat="$2"; shift 2
  "$@" >"$TMP/out.txt" 2>"$TMP/err.txt"
  local rc=$?
  if [ "$rc" -ne 1 ]; then bad "$name (exit $rc, expected 1)" "$TMP/err.txt"; return; fi
  if [ "$(wc -l <"$TMP/err.txt")" -ne 1 ] || ! grep -q -- "$pat" "$TMP/err.txt"; then
    bad "$name (expected one line matching '$pat')" "$TMP/err.txt"; return
  fi
  ok "$name: $(cat "$TMP/err.txt")"
}

if ! "$PY" -c 'import matplotlib, h5py, numpy' 2>"$TMP/err.txt"; then
  bad "$PY has matplotlib and h5py (install python3-matplotlib python3-h5py)" "$TMP/err.txt"
  exit 1
fi

gen() { "$PY" "$GEN" "$@" >"$TMP/gen.txt" 2>&1 || { bad "make_synthetic_h5.py $*" "$TMP/gen.txt"; }; }
gen run  "$TMP/run.h5"
gen run  "$TMP/run_noorient.h5" --drop /support/orientation
gen run  "$TMP/run_noleg.h5" --drop /legs/E/centerline
gen run  "$TMP/run_1.h5" --n 1 --k 2
gen run  "$TMP/run_short.h5" --short /legs/H/centerline
gen bend "$TMP/fem.h5" --model fem --until 0.403
gen bend "$TMP/analytic.h5" --model analytic --m 30 --scale 0.9
gen bend "$TMP/bend_noangle.h5" --drop /angle_deg
printf 'not hdf5\n' >"$TMP/junk.h5"

# plot_track.py
expect_png "plot_track default"            "$TMP/a.png" "$PY" "$TRACK" "$TMP/run.h5" -o "$TMP/a.png"
expect_png "plot_track --reference none --times" "$TMP/b.png" \
  "$PY" "$TRACK" "$TMP/run.h5" -o "$TMP/b.png" --reference none --times 0,3,6,9
expect_png "plot_track --reference obstacle" "$TMP/o.png" \
  "$PY" "$TRACK" "$TMP/run.h5" -o "$TMP/o.png" --reference obstacle
expect_png "plot_track default output name" "$TMP/run_track.png" "$PY" "$TRACK" "$TMP/run.h5"
expect_png "plot_track single sample"       "$TMP/c.png" "$PY" "$TRACK" "$TMP/run_1.h5" -o "$TMP/c.png"
expect_png "plot_track series one sample short" "$TMP/s.png" "$PY" "$TRACK" "$TMP/run_short.h5" -o "$TMP/s.png"
grep -q "plotting the first 36 samples" "$TMP/out.txt" && ok "plot_track warns on short series" \
  || bad "plot_track warns on short series" "$TMP/out.txt"
expect_fail1 "plot_track missing file"      "no such file" "$PY" "$TRACK" "$TMP/nope.h5" -o "$TMP/x.png"
expect_fail1 "plot_track missing orientation" "missing dataset /support/orientation" \
  "$PY" "$TRACK" "$TMP/run_noorient.h5" -o "$TMP/x.png"
expect_fail1 "plot_track missing leg"       "missing dataset /legs/E/centerline" \
  "$PY" "$TRACK" "$TMP/run_noleg.h5" -o "$TMP/x.png"
expect_fail1 "plot_track not HDF5"          "not a readable HDF5 file" "$PY" "$TRACK" "$TMP/junk.h5" -o "$TMP/x.png"

# plot_bend.py
expect_png "plot_bend one file"   "$TMP/d.png" "$PY" "$BEND" "$TMP/fem.h5" -o "$TMP/d.png"
expect_png "plot_bend two models" "$TMP/e.png" "$PY" "$BEND" "$TMP/fem.h5" "$TMP/analytic.h5" -o "$TMP/e.png"
expect_fail1 "plot_bend missing file"    "no such file" "$PY" "$BEND" "$TMP/fem.h5" "$TMP/nope.h5" -o "$TMP/x.png"
expect_fail1 "plot_bend missing dataset" "missing dataset /angle_deg" \
  "$PY" "$BEND" "$TMP/fem.h5" "$TMP/bend_noangle.h5" -o "$TMP/x.png"
[ ! -e "$TMP/x.png" ] && ok "no PNG written on failure" || bad "a failing run wrote $TMP/x.png"

# plot_gait.py: the heat map of a shipped gait, of a two-row table by label, and a bad table
expect_png "plot_gait shipped flat_road.csv" "$TMP/g.png" "$PY" "$GAITMAP" "$ROOT/gaits/flat_road.csv" -o "$TMP/g.png"
# every data row read: the file's lines less comments, blank lines and the header
nrow=$(grep -v '^#' "$ROOT/gaits/flat_road.csv" | grep -c -v '^\s*$')
nrow=$((nrow - 1))
grep -q "heat map of $nrow rows" "$TMP/out.txt" && ok "plot_gait reads every row ($nrow)" \
  || bad "plot_gait reads every row ($nrow)" "$TMP/out.txt"
printf '# two rows\ntime,22,A_II1_O3\n0,0.1,0\n1.5,0,0.25\n' >"$TMP/small.csv"
expect_png "plot_gait by label"   "$TMP/h.png" "$PY" "$GAITMAP" "$TMP/small.csv" -o "$TMP/h.png" --t-end 3
printf 'time,A_II1_O3\n0,0.1\n0,0.2\n' >"$TMP/badtime.csv"
expect_fail1 "plot_gait times must increase" "badtime.csv:3: time 0.0 s is not after 0.0 s" \
  "$PY" "$GAITMAP" "$TMP/badtime.csv" -o "$TMP/x.png"
printf 'time,Z_II1_O3\n0,0.1\n' >"$TMP/badcol.csv"
expect_fail1 "plot_gait unknown column" "badcol.csv:1: column 'Z_II1_O3' is not a chamber" \
  "$PY" "$GAITMAP" "$TMP/badcol.csv" -o "$TMP/x.png"
expect_fail1 "plot_gait missing file" "cannot open gait table" "$PY" "$GAITMAP" "$TMP/nope.csv" -o "$TMP/x.png"
[ ! -e "$TMP/x.png" ] && ok "no heat map written on failure" || bad "a failing heat map wrote $TMP/x.png"

# plot_calibration.py: a mode table with and without the model's predictions, and bad inputs
gen caltable "$TMP/cal.h5"
gen calpred "$TMP/calpred.h5"
gen caltable "$TMP/cal_nobend.h5" --drop /cases/O13/bend
expect_png "plot_calibration with the model" "$TMP/cal/calibration_bend.png" \
  "$PY" "$CALIB" "$TMP/cal.h5" --model "$TMP/calpred.h5" -o "$TMP/cal"
for png in stretch holdout stiffness; do
  [ -s "$TMP/cal/calibration_$png.png" ] && ok "plot_calibration wrote calibration_$png.png" \
    || bad "plot_calibration wrote no calibration_$png.png" "$TMP/out.txt"
done
expect_png "plot_calibration without a model" "$TMP/cal2/calibration_holdout.png" \
  "$PY" "$CALIB" "$TMP/cal.h5" -o "$TMP/cal2"
expect_fail1 "plot_calibration not a mode table" "not an FE calibration table of modes" \
  "$PY" "$CALIB" "$TMP/fem.h5" -o "$TMP/cal3"
expect_fail1 "plot_calibration missing dataset" "missing dataset /cases/O13/bend" \
  "$PY" "$CALIB" "$TMP/cal_nobend.h5" -o "$TMP/cal3"
expect_fail1 "plot_calibration missing model file" "no such file" \
  "$PY" "$CALIB" "$TMP/cal.h5" --model "$TMP/nope.h5" -o "$TMP/cal3"
[ ! -e "$TMP/cal3/calibration_bend.png" ] && ok "no calibration PNG written on failure" \
  || bad "a failing plot_calibration wrote a PNG"

# stance_slip.py: the per-foot analysis of a run file (the synthetic run's feet advance 39 mm
# per stride), and bad inputs
if "$PY" "$SLIP" "$TMP/run.h5" >"$TMP/out.txt" 2>&1 && grep -q "per stride" "$TMP/out.txt"; then
  ok "stance_slip reads a run file"
else
  bad "stance_slip reads a run file" "$TMP/out.txt"
fi
expect_fail1 "stance_slip not HDF5" "stance_slip: .*junk.h5" "$PY" "$SLIP" "$TMP/junk.h5"
expect_fail1 "stance_slip missing centreline" "stance_slip: .*run_noleg.h5" \
  "$PY" "$SLIP" "$TMP/run_noleg.h5"
expect_fail1 "stance_slip missing file" "stance_slip: .*nope.h5" "$PY" "$SLIP" "$TMP/nope.h5"

# rod_vs_fe.py: the rod level with the shipped FE mode table against the FE on the table's
# never-fitted cases. H1 (unequal pressures, to 0.3 MPa), H2 (three chambers, 0.2 MPa) and O2
# (Omega2 alone, the symmetry case, to 0.4 MPa) met 2 % of the leg when measured (0.72, 0.73,
# 0.17 %): a broken rod, map or reader moves them by far more
MODES="$ROOT/robot/calibration_fe_leg_modes.h5"
if "$PY" "$RODFE" "$MODES" --crawlsim "$EXE" --cases H1,H2,O2 --png "$TMP/rodfe.png" \
    >"$TMP/out.txt" 2>&1 && [ "$(grep -c '| meets |' "$TMP/out.txt")" -eq 3 ] && [ -s "$TMP/rodfe.png" ]; then
  ok "rod_vs_fe: the rod meets 2 % of the leg on H1, H2, O2"
else
  bad "rod_vs_fe: the rod meets 2 % of the leg on H1, H2, O2" "$TMP/out.txt"
fi
# the same on the symmetric-mesh table under rbf-pair (issue 8's table): H5-H7 and H11, which
# the 9-mode table misses above 0.225-0.25 MPa, and the 0.05 N tip load against the FE on that
# mesh met 2 % when measured (2026-12-04: 0.58, 0.94, 0.24, 1.28, 1.45 %)
SYM="$ROOT/robot/calibration_fe_leg_modes_sym.h5"
if "$PY" "$RODFE" "$SYM" --cal-rule rbf-pair --crawlsim "$EXE" --cases H5,H6,H7,H11 \
    --loaded "$ROOT/docs/bench/rod_vs_fe_sym_2026-12-04/fe_leg_O12_tip_x0.05N_L4_sym.h5" \
    >"$TMP/out.txt" 2>&1 && [ "$(grep -c '| meets |' "$TMP/out.txt")" -eq 5 ]; then
  ok "rod_vs_fe: on the symmetric table the rod meets 2 % on H5, H6, H7, H11 and the tip load"
else
  bad "rod_vs_fe: on the symmetric table the rod meets 2 % on H5, H6, H7, H11 and the tip load" \
    "$TMP/out.txt"
fi
# --extra: held-out cases of a case file that is not merged into the table (here H2, copied out
# of the table into a file of its own) are compared like the table's own
"$PY" - "$MODES" "$TMP/extra_H2.h5" <<'PYEOF'
import sys, h5py
with h5py.File(sys.argv[1], "r") as src, h5py.File(sys.argv[2], "w") as dst:
    for k, v in src.attrs.items():
        dst.attrs[k] = v
    src.copy("/cases/H2", dst, name="/cases/H2")
PYEOF
if "$PY" "$RODFE" "$MODES" --crawlsim "$EXE" --cases O2 --extra "$TMP/extra_H2.h5" \
    >"$TMP/out.txt" 2>&1 && [ "$(grep -c '| meets |' "$TMP/out.txt")" -eq 2 ] \
    && grep -q '^| H2 |' "$TMP/out.txt"; then
  ok "rod_vs_fe --extra: a case file's held-out case is compared"
else
  bad "rod_vs_fe --extra: a case file's held-out case is compared" "$TMP/out.txt"
fi
expect_fail1 "rod_vs_fe extra file without cases" "fem.h5: missing group /cases" \
  "$PY" "$RODFE" "$MODES" --crawlsim "$EXE" --cases O2 --extra "$TMP/fem.h5"
expect_fail1 "rod_vs_fe no such case" "rod_vs_fe.py: .*no case H99" \
  "$PY" "$RODFE" "$MODES" --crawlsim "$EXE" --cases H99
expect_fail1 "rod_vs_fe not a mode table" "not an FE calibration table of modes" \
  "$PY" "$RODFE" "$TMP/fem.h5" --crawlsim "$EXE"
expect_fail1 "rod_vs_fe missing file" "rod_vs_fe.py: .*nope.h5: no such file" \
  "$PY" "$RODFE" "$TMP/nope.h5" --crawlsim "$EXE"
expect_fail1 "rod_vs_fe loaded file not a bend file" "cal.h5: missing dataset /pressure" \
  "$PY" "$RODFE" "$MODES" --crawlsim "$EXE" --cases H2 --loaded "$TMP/cal.h5"

# bench_levels.py --plot-only: the chart again from a levels_bench.csv, no runs
LEVELS="$ROOT/tools/bench_levels.py"
mkdir -p "$TMP/lv" "$TMP/lvbad"
cat >"$TMP/lv/levels_bench.csv" <<'CSV'
task,model,setting,error_mm,cpu_s,wall_s,sim_s,load,status,reference,command
flat-road,rod,"links 6, macro 1 x 0.25 ms",0,12.4,12.46,9.5,1.5,ok,yes,run
flat-road,rod,"links 4, macro 1 x 1 ms",6.77,10.7,10.8,9.5,1.5,ok,,run
flat-road,prb,"links 4, dt 1 ms",29.1,30.2,30.3,9.5,1.5,ok,,run
(1) bend O12,fe,mesh 6 mm,20.2,127,127,,1.0,ok,,bend
CSV
expect_png "bench_levels --plot-only" "$TMP/lv/levels_pareto.png" \
  "$PY" "$LEVELS" --plot-only --out-dir "$TMP/lv" --table "$TMP/lv/none.csv"
printf 'task,model,setting,error_mm,cpu_s,wall_s\nflat-road,rod,x,1,1,1\n' >"$TMP/lvbad/levels_bench.csv"
expect_fail1 "bench_levels --plot-only short row" "levels_bench.csv:2: not a levels_bench.csv row" \
  "$PY" "$LEVELS" --plot-only --out-dir "$TMP/lvbad" --table "$TMP/lv/none.csv"
mkdir -p "$TMP/lvnan"
printf 'task,model,setting,error_mm,cpu_s,wall_s,status,reference\nflat-road,rod,x,abc,1,1,ok,\n' \
  >"$TMP/lvnan/levels_bench.csv"
expect_fail1 "bench_levels --plot-only not a number" "levels_bench.csv:2: error_mm, cpu_s or wall_s" \
  "$PY" "$LEVELS" --plot-only --out-dir "$TMP/lvnan" --table "$TMP/lv/none.csv"
# bench_levels.py --whole-fill: a table it cannot read is one line naming file and line, before
# any run (and the file is left as it was)
printf '# c\nscene,level,links,dt_s\nflat-road,rod,8,0.001\n' >"$TMP/lv/nocol.csv"
expect_fail1 "bench_levels --whole-fill header without error_mm" "nocol.csv:2: the header has no column error_mm" \
  "$PY" "$LEVELS" --crawlsim "$EXE" --work "$TMP/lv/W" --whole-fill "$TMP/lv/nocol.csv"
printf 'scene,level,links,macro_steps,dt_s,error_mm,cpu_s_per_s,wall_s_per_s,machine\nflat-road,rod,8,1,0.001,3.3,1.2,1.2,m,extra\n' \
  >"$TMP/lv/extra.csv"
expect_fail1 "bench_levels --whole-fill row with an extra field" "extra.csv:2: 10 fields, expected 9" \
  "$PY" "$LEVELS" --crawlsim "$EXE" --work "$TMP/lv/W" --whole-fill "$TMP/lv/extra.csv"
if grep -q extra "$TMP/lv/extra.csv"; then ok "bench_levels --whole-fill left the bad table as it was"; else bad "bench_levels --whole-fill rewrote a table it refused" "$TMP/lv/extra.csv"; fi
expect_fail1 "bench_levels --plot-only no CSV" "levels_bench.csv: cannot read" \
  "$PY" "$LEVELS" --plot-only --out-dir "$TMP/nope" --table "$TMP/lv/none.csv"

# tools/gait_search.py: the shipped searched gait is the script's description of the parameters
# its header names (so the committed result table's best row is what ships), and bad parameters
# are one line and exit 1
SEARCH="$ROOT/tools/gait_search.py"
params=$(sed -n 's/^# params: //p' "$ROOT/gaits/flat_road_rod.gait")
tramp=$(sed -n 's/^ramp //p' "$ROOT/gaits/flat_road_rod.gait")  # the design's stated actuation time
if "$PY" "$SEARCH" --write-gait "$TMP/fr.gait" --params "$params" ${tramp:+--table-ramp "$tramp"} \
     >"$TMP/out.txt" 2>&1 &&
   cmp -s "$TMP/fr.gait" "$ROOT/gaits/flat_road_rod.gait"; then
  ok "gait_search --write-gait reproduces gaits/flat_road_rod.gait ($params)"
else
  bad "gait_search --write-gait reproduces gaits/flat_road_rod.gait ($params)" "$TMP/out.txt"
fi
expect_fail1 "gait_search bad --params" "gait_search.py: --params '1,2': expected four numbers" \
  "$PY" "$SEARCH" --write-gait "$TMP/bad.gait" --params 1,2
expect_fail1 "gait_search --params outside the box" "outside the search's box" \
  "$PY" "$SEARCH" --write-gait "$TMP/bad.gait" --params 100,3,11,0.2
expect_fail1 "gait_search --step-tol without strain legs" "strain legs only" \
  "$PY" "$SEARCH" --strain-step adaptive --step-tol 5e-4 --evals 0
expect_fail1 "gait_search --step-tol with a fixed strain step" "with --strain-step adaptive only" \
  "$PY" "$SEARCH" --legs strain --step-tol 5e-4 --evals 0

# tools/obstacle_search.py: its start (the free parameters at their listed defaults) is
# obstacle_gait.py's design with --base alone (the same statements), a design off the defaults
# is another table, and bad input is one line and exit 1
OS="$ROOT/tools/obstacle_search.py"
OG="$ROOT/tools/obstacle_gait.py"
stmts() { grep -v '^#' "$1"; }
if "$PY" "$OS" --write-gait "$TMP/os0.gait" >"$TMP/out.txt" 2>&1 &&
   "$PY" "$OG" --up-short -1 --over-step -3 --reach 55 --clear-down -o "$TMP/og0.gait" >>"$TMP/out.txt" 2>&1 &&
   cmp -s <(stmts "$TMP/os0.gait") <(stmts "$TMP/og0.gait"); then
  ok "obstacle_search's start is obstacle_gait.py with --base alone"
else
  bad "obstacle_search's start is obstacle_gait.py with --base alone" "$TMP/out.txt"
fi
if "$PY" "$OS" --write-gait "$TMP/os1.gait" --free settle,Tclimb --x0 0.9,0.9 >"$TMP/out.txt" 2>&1 &&
   "$PY" "$OG" --up-short -1 --over-step -3 --reach 55 --clear-down --settle 0.9 --Tclimb 0.9 \
     -o "$TMP/og1.gait" >>"$TMP/out.txt" 2>&1 &&
   cmp -s <(stmts "$TMP/os1.gait") <(stmts "$TMP/og1.gait") &&
   ! cmp -s <(stmts "$TMP/os1.gait") <(stmts "$TMP/os0.gait"); then
  ok "obstacle_search --x0 sets its free parameters' options (another table)"
else
  bad "obstacle_search --x0 sets its free parameters' options (another table)" "$TMP/out.txt"
fi
expect_fail1 "obstacle_search bad --free" "obstacle_search.py: --free 'foo': names among" \
  "$PY" "$OS" --free foo --write-gait "$TMP/bad.gait"
expect_fail1 "obstacle_search --x0 outside the box" "within its box" \
  "$PY" "$OS" --free settle --x0 5 --write-gait "$TMP/bad.gait"
expect_fail1 "obstacle_search --report-only runs nothing" "no design evaluated yet" \
  "$PY" "$OS" --dir "$TMP/os_empty" --report-only --crawlsim "$EXE"
# the model (--legs, --links, the step flags) is in the case key as gait_search.py has it: the
# same statements, another key per model; the set's step halved is the model's (the tolerance
# halved on adaptive strain legs, the step on rod legs), never the set's placeholder word
oskey() { "$PY" "$OS" --write-gait "$TMP/$1.gait" "${@:2}" >"$TMP/$1.txt" 2>&1 && cut -d: -f1 "$TMP/$1.txt"; }
k0=$(oskey osm0); k1=$(oskey osm1 --legs strain)
k2=$(oskey osm2 --legs strain --strain-step adaptive --step-tol 5e-4); k3=$(oskey osm3 --legs rod --links 8)
if [ -n "$k0" ] && [ -n "$k1" ] && [ -n "$k2" ] && [ -n "$k3" ] &&
   [ "$k0" != "$k1" ] && [ "$k1" != "$k2" ] && [ "$k0" != "$k3" ] &&
   cmp -s "$TMP/osm0.gait" "$TMP/osm1.gait" && cmp -s "$TMP/osm0.gait" "$TMP/osm2.gait" &&
   ! grep -q "runs:" "$TMP/osm0.txt" && grep -q "step halved: --dt 0.0005$" "$TMP/osm0.txt" &&
   grep -q "runs: --legs strain; .*step halved: --step-tol 0.000125$" "$TMP/osm1.txt" &&
   grep -q "step halved: --step-tol 0.00025$" "$TMP/osm2.txt" && grep -q "runs: --links 8 --legs rod;" "$TMP/osm3.txt"; then
  ok "obstacle_search: the model in the case key ($k0 $k1 $k2 $k3), the same statements, the model's step halved"
else
  bad "obstacle_search: the model in the case key ($k0 $k1 $k2 $k3), the same statements, the model's step halved" \
    <(cat "$TMP"/osm[0-3].txt)
fi
expect_fail1 "obstacle_search --step-tol without strain legs" "strain legs only" \
  "$PY" "$OS" --strain-step adaptive --step-tol 5e-4 --write-gait "$TMP/bad.gait"
expect_fail1 "obstacle_search --step-tol with a fixed strain step" "with --strain-step adaptive only" \
  "$PY" "$OS" --legs strain --step-tol 5e-4 --write-gait "$TMP/bad.gait"

# tools/obstacle_gait.py rule 17 (--up-short): on by default at the measured 30 mm (the shipped
# description bf50, byte for byte); it moves the second pair's first landing onto the step
# (expected on the edge's corner) to the offset that clears it, the same statements as forcing
# that offset with the rule off, and only that step; off (--up-short -1) it writes k3, another
# table; a bad --up-band is one line and exit 1
if "$PY" "$OG" -o "$TMP/r17.gait" >"$TMP/out.txt" 2>&1 && cmp -s "$TMP/r17.gait" "$ROOT/gaits/obstacle.gait" &&
   "$PY" "$OG" --up-short -1 -o "$TMP/k3.gait" >>"$TMP/out.txt" 2>&1 &&
   "$PY" "$OG" --up-short -1 --force BF:0:50 --force BF:4:35 -o "$TMP/bf50.gait" >>"$TMP/out.txt" 2>&1 &&
   cmp -s <(stmts "$TMP/r17.gait") <(stmts "$TMP/bf50.gait") &&
   ! cmp -s <(stmts "$TMP/r17.gait") <(stmts "$TMP/k3.gait") &&
   [ "$(grep -c 'rule 17: landing' "$TMP/r17.gait")" -eq 2 ] &&
   [ "$(grep -c 'rule 17: landing' "$TMP/k3.gait")" -eq 0 ]; then
  ok "obstacle_gait rule 17 on by default (the shipped bf50): B, F's climbing landing at offset 50; off writes k3"
else
  bad "obstacle_gait rule 17 on by default (the shipped bf50): B, F's climbing landing at offset 50; off writes k3" "$TMP/out.txt"
fi
expect_fail1 "obstacle_gait bad --up-band" "obstacle_gait.py: --up-band takes two numbers" \
  "$PY" "$OG" --up-short 30 --up-band 5,5 -o "$TMP/bad.gait"

# tools/obstacle_gait.py --gate-from: the shipped gate's gates are the shipped description's (the
# same statements; --gate-from writes no crawl or walk statement, the shipped gate has both); a lift is a
# pair's first move into a step, to AM or AP by its stance offset (rule 17's B, F lift to AP10 at 7.4 s) or U0, never its move over (k3's D, H climb at 9.4 s: AM15,
# then over to U0 at 9.6 s)
if "$PY" "$OG" --gate-from "$ROOT/gaits/obstacle.gait" --gate-out "$TMP/g.gate" >"$TMP/out.txt" 2>&1 &&
   ! grep -q '^crawl' "$TMP/g.gate" &&
   ! grep -q '^walk' "$TMP/g.gate" &&
   cmp -s <(stmts "$TMP/g.gate") <(stmts "$ROOT/gaits/obstacle.gate" | grep -v '^crawl\|^walk') &&
   grep -q '^move 7.4000 [0-9.]* BF AP10$' "$ROOT/gaits/obstacle.gait" &&
   grep -q '^gate 7.4000 CG  # lift of BF' "$TMP/g.gate" &&
   "$PY" "$OG" --up-short -1 --gate-swing none --gate-land none -o "$TMP/k3g.gait" \
     --gate-out "$TMP/k3g.gate" >>"$TMP/out.txt" 2>&1 &&
   grep -q '^move 9.6000 [0-9.]* DH U0$' "$TMP/k3g.gait" && grep -q '^gate 9.4000 AE' "$TMP/k3g.gate" &&
   ! grep -q '^gate 9.6000' "$TMP/k3g.gate"; then
  ok "obstacle_gait --gate-from: the shipped gate; a lift to AP gated, a move over to U0 not"
else
  bad "obstacle_gait --gate-from: the shipped gate; a lift to AP gated, a move over to U0 not" "$TMP/out.txt"
fi

# tools/obstacle_gait.py --foothold-out (rule 15): each candidate is designed with the forces in
# effect, the default BF:4:35 included (before margin18 a candidate of the default description
# lost it, changed other legs and stopped the tool), and writes no gate (before, each candidate's
# own run overwrote --gate-out): the gate is the nominal description's, the shipped one
if (cd "$ROOT" && "$PY" "$OG" --foothold BF:1:35 -o "$TMP/fh.gait" --gate-out "$TMP/fh.gate" \
      --foothold-out "$TMP/fh" --crawlsim "$EXE") >"$TMP/out.txt" 2>&1 &&
   grep -q "^# the landing gate of $TMP/fh.gait " "$TMP/fh.gate" &&
   cmp -s <(stmts "$TMP/fh.gate") <(stmts "$ROOT/gaits/obstacle.gate") &&
   cmp -s <(stmts "$TMP/fh.csv") <(stmts "$ROOT/gaits/obstacle.csv") &&
   grep -q '^foothold 7.4000 BF xplan ' "$TMP/fh.foothold" &&
   grep -q '^candidate 35 land [0-9.]* fits [-0-9e.+]* [-0-9e.+]* fh.foothold.d/f1_BF_35.csv$' "$TMP/fh.foothold"; then
  ok "obstacle_gait --foothold-out: candidates keep the default force, the gate is the nominal's"
else
  bad "obstacle_gait --foothold-out: candidates keep the default force, the gate is the nominal's" "$TMP/out.txt"
fi

# tools/obstacle_gait.py --crawl-max (issue 33, the crawl ended on the measured support): 12 by
# default since ship11 (the shipped description and gate, byte for byte, the gate's `crawl`
# statement at the crawl's start the description names: 12 lateral slots); --crawl-max 0 writes
# the table shipped before (8 slots = zend / (Dz / 2), no statement, the same gates); N < 3 is
# refused
if "$PY" "$OG" -o "$TMP/c12.gait" --gate-out "$TMP/c12.gate" >"$TMP/out.txt" 2>&1 &&
   cmp -s "$TMP/c12.gait" "$ROOT/gaits/obstacle.gait" &&
   cmp -s <(stmts "$TMP/c12.gate") <(stmts "$ROOT/gaits/obstacle.gate") &&
   T0=$(sed -n 's/^# the lateral crawl: 12 slots of 0.55 s from \([0-9.]*\) s.*/\1/p' "$TMP/c12.gait") &&
   [ -n "$T0" ] && grep -q "^crawl $T0""00 0.55 12 270 23\$" "$TMP/c12.gate" &&
   "$PY" "$OG" --crawl-max 0 -o "$TMP/c0.gait" --gate-out "$TMP/c0.gate" >>"$TMP/out.txt" 2>&1 &&
   grep -q '^# the lateral crawl: 8 slots of 0.55 s from' "$TMP/c0.gait" &&
   ! grep -q '^crawl' "$TMP/c0.gate" &&
   cmp -s <(stmts "$TMP/c0.gate") <(stmts "$ROOT/gaits/obstacle.gate" | grep -v '^crawl') &&
   ! cmp -s <(stmts "$TMP/c0.gait") <(stmts "$ROOT/gaits/obstacle.gait"); then
  ok "obstacle_gait --crawl-max: 12 by default (the shipped files); 0 writes 8 slots and no crawl statement"
else
  bad "obstacle_gait --crawl-max: 12 by default (the shipped files); 0 writes 8 slots and no crawl statement" "$TMP/out.txt"
fi
expect_fail1 "obstacle_gait bad --crawl-max" "obstacle_gait.py: --crawl-max takes N >= 3" \
  "$PY" "$OG" --crawl-max 2 -o "$TMP/bad.gait"

# tools/obstacle_gait.py --walk-extra (issue 33, obst13, rule 21: the walk in two groups ended on
# the measured support): 1 by default (the shipped description and gate: the `walk` statement
# from the walk's first slot after the step ahead, the slots before the turn, 646 and 65 mm,
# then the crawl a cycle later); --walk-extra 0 writes the table shipped before obst13 (4 slots,
# no statement, the same gates, the crawl at the turn's end one cycle sooner); with it the
# table's rows are the same to the decision's boundary; K < 0 is refused
if "$PY" "$OG" --walk-extra 0 -o "$TMP/w0.gait" --gate-out "$TMP/w0.gate" >"$TMP/out.txt" 2>&1 &&
   "$PY" "$OG" -o "$TMP/w1.gait" --gate-out "$TMP/w1.gate" >>"$TMP/out.txt" 2>&1 &&
   cmp -s "$TMP/w1.gait" "$ROOT/gaits/obstacle.gait" &&
   W0=$(sed -n 's/^# from \([0-9.]*\) s (support planned at x + [0-9]* mm): two groups.*/\1/p' "$TMP/w1.gait") &&
   [ -n "$W0" ] && WT=$(awk -v t="$W0" 'BEGIN { printf "%.4f", t + 0.55 }') &&
   grep -q "^walk $WT 0.55 5 646 65\$" "$TMP/w1.gate" && ! grep -q '^walk' "$TMP/w0.gate" &&
   C0=$(sed -n 's/^crawl \([0-9.]*\) .*/\1/p' "$TMP/w0.gate") &&
   C1=$(sed -n 's/^crawl \([0-9.]*\) .*/\1/p' "$TMP/w1.gate") &&
   awk -v a="$C0" -v b="$C1" 'BEGIN { exit !(b - a > 1.0999 && b - a < 1.1001) }' &&
   cmp -s <(stmts "$TMP/w0.gate" | grep -v '^crawl') <(stmts "$TMP/w1.gate" | grep -v '^crawl\|^walk') &&
   cmp -s <(awk -v t="$WT" '$1 == "move" && $2 + 0 < t + 1.6499' "$TMP/w0.gait") \
          <(awk -v t="$WT" '$1 == "move" && $2 + 0 < t + 1.6499' "$TMP/w1.gait") &&
   ! cmp -s <(stmts "$TMP/w0.gait") <(stmts "$TMP/w1.gait"); then
  ok "obstacle_gait --walk-extra: 1 by default (the shipped files, the walk statement); 0 writes the table before, no statement, the same gates"
else
  bad "obstacle_gait --walk-extra: 1 by default (the shipped files, the walk statement); 0 writes the table before, no statement, the same gates" "$TMP/out.txt"
fi
expect_fail1 "obstacle_gait bad --walk-extra" "obstacle_gait.py: --walk-extra takes K >= 0" \
  "$PY" "$OG" --walk-extra -1 -o "$TMP/bad.gait"

# tools/obstacle_gait.py --gate-land / --gate-x (issue 33, ramp11; the shipped gate has the
# set-down gates of --gate-land's default and no x): the description is the same; with the
# swing and set-down gates off, --gate-land 13.3:13.4 adds one gate, the
# set-down of the pair lifting in that window (A, E's step down), on the pair itself; --gate-x
# 25:13.7:13.8 gives it `x XMIN`, the plan's support x there less 25 mm, between the plan's x at
# the cycles around it (cycle 3's less 25 and cycle 4's less 25)
if "$PY" "$OG" --gate-land none --gate-swing none -o "$TMP/gp.gait" --gate-out "$TMP/gp.gate" \
     >"$TMP/out.txt" 2>&1 &&
   "$PY" "$OG" --gate-land 13.3:13.4 --gate-swing none --gate-x 25:13.7:13.8 -o "$TMP/gl.gait" \
     --gate-out "$TMP/gl.gate" >>"$TMP/out.txt" 2>&1 &&
   grep -q 'set-down' "$ROOT/gaits/obstacle.gate" && ! grep -q ' x ' "$ROOT/gaits/obstacle.gate" &&
   cmp -s "$TMP/gp.gait" "$TMP/gl.gait" &&
   [ "$(diff <(stmts "$TMP/gp.gate") <(stmts "$TMP/gl.gate") | grep -c '^[<>]')" = 1 ] &&
   L=$(diff <(stmts "$TMP/gp.gate") <(stmts "$TMP/gl.gate") | sed -n 's/^> //p') &&
   X=$(echo "$L" | sed -n 's/^gate 13.7100 AE x \([0-9.]*\)  # set-down of AE$/\1/p') &&
   X3=$(sed -n 's/^# cycle 3 from [0-9.]* s: support planned at x + \([0-9]*\) mm$/\1/p' "$TMP/gl.gait") &&
   X4=$(sed -n 's/^# cycle 4 from [0-9.]* s: support planned at x + \([0-9]*\) mm$/\1/p' "$TMP/gl.gait") &&
   awk -v x="$X" -v a="$X3" -v b="$X4" 'BEGIN { exit !(x > a - 25 && x < b - 25) }'; then
  ok "obstacle_gait --gate-land/--gate-x: the shipped gate's set-downs, no x; A, E's set-down gated at x $X (plan $X3..$X4 less 25)"
else
  bad "obstacle_gait --gate-land/--gate-x: the shipped gate's set-downs, no x; one set-down gate with x" "$TMP/out.txt"
fi
expect_fail1 "obstacle_gait bad --gate-x" "obstacle_gait.py: --gate-x takes MM:T0:T1" \
  "$PY" "$OG" --gate-x 25:13 -o "$TMP/bad.gait"

# tools/obstacle_gait.py rule 18 (--push): off by default (--push 0 writes the shipped description
# byte for byte); --push 1 writes one slot, before the rear pair's step toward the up edge, in
# which no pair lifts (only linear stance moves start in it) and the wave has fewer lifts; a
# negative --push is one line and exit 1
lifts() { awk '$1=="move" && length($4)==2 && ($5 ~ /^AM/ || $5=="U0")' "$1"; }
if "$PY" "$OG" --push 0 -o "$TMP/p0.gait" >"$TMP/out.txt" 2>&1 && cmp -s "$TMP/p0.gait" "$ROOT/gaits/obstacle.gait" &&
   "$PY" "$OG" --push 1 -o "$TMP/p1.gait" >>"$TMP/out.txt" 2>&1 &&
   [ "$(grep -c '^# rule 18: ' "$TMP/p1.gait")" -eq 1 ] &&
   win=$(sed -n 's/^# rule 18: \([0-9.]*\)\.\.\([0-9.]*\) s .*/\1 \2/p' "$TMP/p1.gait") &&
   [ -n "$win" ] &&
   [ "$(awk -v w="$win" 'BEGIN{split(w,b," ")} $1=="move" && $2+0>=b[1]+0 && $2+0<b[2]+0 && $NF!="linear"' \
        "$TMP/p1.gait" | wc -l)" -eq 0 ] &&
   [ "$(awk -v w="$win" 'BEGIN{split(w,b," ")} $1=="move" && $2+0>=b[1]+0 && $2+0<b[2]+0' \
        "$TMP/p1.gait" | wc -l)" -gt 0 ] &&
   [ "$(lifts "$TMP/p1.gait" | wc -l)" -lt "$(lifts "$TMP/p0.gait" | wc -l)" ]; then
  ok "obstacle_gait rule 18 off by default; --push 1 holds one slot in which no pair lifts"
else
  bad "obstacle_gait rule 18 off by default; --push 1 holds one slot in which no pair lifts" "$TMP/out.txt"
fi
expect_fail1 "obstacle_gait negative --push" "obstacle_gait.py: --push takes a number of slots" \
  "$PY" "$OG" --push -1 -o "$TMP/bad.gait"
# rule 19 (--down-lead): from the front pair's first step down to the road the landings are
# planned with the hips that far ahead: one such step, later landings further ahead, a shorter wave
if "$PY" "$OG" --push 1 -o "$TMP/p1.gait" >"$TMP/out.txt" 2>&1 &&
   "$PY" "$OG" --push 1 --down-lead 60 -o "$TMP/l60.gait" >>"$TMP/out.txt" 2>&1 &&
   [ "$(grep -c '^# rule 19: ' "$TMP/l60.gait")" -eq 1 ] && [ "$(grep -c '^# rule 19: ' "$TMP/p1.gait")" -eq 0 ] &&
   [ "$(lifts "$TMP/l60.gait" | wc -l)" -lt "$(lifts "$TMP/p1.gait" | wc -l)" ] &&
   sed -n '/^# cycle 0 /,/^# rule 19: /p' "$TMP/l60.gait" | grep -v '^# rule 19: ' >"$TMP/l60.head" &&
   cmp -s "$TMP/l60.head" <(sed -n '/^# cycle 0 /,$p' "$TMP/p1.gait" | head -n "$(wc -l <"$TMP/l60.head")") &&
   diff <(sed -n '/^# the walk/,$p' "$TMP/p1.gait") <(sed -n '/^# the walk/,$p' "$TMP/l60.gait") |
     grep -q 'foot to'; then
  ok "obstacle_gait rule 19 off by default; --down-lead 60 moves the landings after the step down"
else
  bad "obstacle_gait rule 19 off by default; --down-lead 60 moves the landings after the step down" "$TMP/out.txt"
fi
expect_fail1 "obstacle_gait negative --down-lead" "obstacle_gait.py: --push takes" \
  "$PY" "$OG" --down-lead -5 -o "$TMP/bad.gait"
# tools/obstacle_gait.py rule 20 (--zoverlap): off by default (above: the shipped description byte
# for byte); on, the description before the lateral crawl is unchanged and at every hand-over of
# the crawl after its first the landing group is down (its set-down's end) O before the standing
# group lifts, every stance foot moving at --SHZ per --Tpz; a bad value is one line and exit 1
if "$PY" "$OG" --up-short 30 --zoverlap 0.1 -o "$TMP/r20.gait" >"$TMP/out.txt" 2>&1 &&
   cmp -s <(sed '/^# the lateral crawl:/,$d' "$TMP/r17.gait" | grep -v '^#' | grep -v '^pose') \
          <(sed '/^# the lateral crawl:/,$d' "$TMP/r20.gait" | grep -v '^#' | grep -v '^pose') &&
   "$PY" - "$TMP/r20.gait" >>"$TMP/out.txt" 2>&1 <<'PYEOF'
import re, sys
text = open(sys.argv[1]).read()
crawl = text[text.index('# the lateral crawl:'):text.index('# the feet back under the hips')]
moves = [(float(m[0]), float(m[1]), m[2], m[3], bool(m[4])) for m in
         re.findall(r'move (\S+) (\S+) (\S+) (\S+)( linear)?', crawl)]
lands = sorted(t + d for t, d, legs, pose, lin in moves if pose.startswith('L15P') and not lin)
lifts = sorted(t for t, d, legs, pose, lin in moves if pose.startswith('VLM'))
gaps = [round(lf - ld, 4) for ld, lf in zip(lands, lifts)]
nslots = int(re.search(r'# the lateral crawl: (\d+) slots', crawl).group(1))  # 12 since ship11
assert nslots >= 3 and len(lifts) == nslots - 1 and all(g == 0.1 for g in gaps), gaps  # N - 1 hand-overs
print('hand-overs', gaps)
PYEOF
then
  ok "obstacle_gait rule 20: --zoverlap 0.1 changes only the lateral crawl, both groups down 0.1 s at each hand-over"
else
  bad "obstacle_gait rule 20: --zoverlap 0.1 changes only the lateral crawl, both groups down 0.1 s at each hand-over" "$TMP/out.txt"
fi
expect_fail1 "obstacle_gait bad --zoverlap" "obstacle_gait.py: --zoverlap takes a time in 0..--Tpz" \
  "$PY" "$OG" --zoverlap 0.6 -o "$TMP/bad.gait"

# tools/earth_gait.py: the shipped earth gait is the script's description of the values its
# header names; bad input is one line and exit 1. tools/earth_track.py: a missing run file is
# one line and exit 1
EG="$ROOT/tools/earth_gait.py"
eg_args=$(sed -n 's/^#   T \([0-9.]*\) s, SH \([0-9.]*\) mm, bias \([-0-9.]*\) mm, U \([0-9.]*\) mm, rise \([0-9.]*\) mm.*/--T \1 --SH \2 --bias \3 --U \4 --rise \5/p' "$ROOT/gaits/flat_road_earth.gait")
if [ -n "$eg_args" ] && "$PY" "$EG" $eg_args -o "$TMP/fre.gait" >"$TMP/out.txt" 2>&1 &&
   cmp -s "$TMP/fre.gait" "$ROOT/gaits/flat_road_earth.gait"; then
  ok "earth_gait reproduces gaits/flat_road_earth.gait ($eg_args)"
else
  bad "earth_gait reproduces gaits/flat_road_earth.gait ($eg_args)" "$TMP/out.txt"
fi
expect_fail1 "earth_gait bad --frac" "earth_gait.py: --frac needs four fractions" \
  "$PY" "$EG" --frac 0.5,0.5 -o "$TMP/bad.gait"
expect_fail1 "earth_track missing file" "earth_track.py: $TMP/none.h5: not a run file" \
  "$PY" "$ROOT/tools/earth_track.py" "$TMP/none.h5"

echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
