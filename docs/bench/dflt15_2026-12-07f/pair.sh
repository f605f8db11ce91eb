#!/bin/sh
# pair.sh CASE "SCENE ARGS" DEF_TOL BDF_TOL: one case of dflt15's batch, run twice at the same
# time (so both see the same load): the strain level's default step (backward Euler, adaptive;
# `--step-tol DEF_TOL` unless DEF_TOL is `-`, the default's 2.5e-4 mm) as tag d_CASE, and the
# adaptive BDF2 (`--strain-step adaptive --step-order 2 --step-tol BDF_TOL`) as tag b_CASE.
# Each: `crawlsim run --scene ... ARGS --out $D/TAG.h5`, nice 5; the log logs/TAG.log holds
# uptime before and after, the command, the run's banner and summary, /usr/bin/time's user
# CPU and wall, and `rc N` (a run that falls exits 1: a result too). A tag whose log has its
# rc line is skipped (resumable). D default /tmp/dflt15/runs, CRAWLSIM default
# /tmp/dflt15/crawlsim (a copy of this branch's build before any change: main 9fc24f8's code).
# From the worktree.
N=$1; A=$2; DT=$3; BT=$4
H=$(dirname "$0")
D=${D:-/tmp/dflt15/runs}; C=${CRAWLSIM:-/tmp/dflt15/crawlsim}; L=$H/logs
mkdir -p "$D" "$L"
one() {  # TAG FLAGS...
  tag=$1; shift
  if [ -f "$L/$tag.log" ] && grep -q '^rc ' "$L/$tag.log"; then return 0; fi
  { uptime; echo "crawlsim run $A $* --out $D/$tag.h5"
    # shellcheck disable=SC2086
    /usr/bin/time -f "%U user %S sys %e wall" nice -n 5 "$C" run $A "$@" --out "$D/$tag.h5"
    echo "rc $?"; uptime; } > "$L/$tag.log" 2>&1
  rm -f "$D/$tag.xdmf"
}
if [ "$DT" = "-" ]; then DA=; else DA="--step-tol $DT"; fi
# shellcheck disable=SC2086
one d_$N $DA &
one b_$N --strain-step adaptive --step-order 2 --step-tol "$BT" &
wait
echo "$N: d $(grep '^rc ' "$L/d_$N.log"), b $(grep '^rc ' "$L/b_$N.log") ($(date -u +%H:%M))"
