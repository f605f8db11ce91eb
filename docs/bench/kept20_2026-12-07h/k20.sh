#!/bin/sh
# k20.sh SCRIPT ARGS...: legpass19's SCRIPT (runs.sh, cgrun.sh or compare.py, in
# ../legpass19_2026-12-07h) run on /tmp/kept20 in place of /tmp/legpass19 (binaries in
# /tmp/kept20/bin, runs in /tmp/kept20/runs, profiles in /tmp/kept20/cg), its paths resolved
D=$(cd "$(dirname "$0")/../legpass19_2026-12-07h" && pwd)
S=$1; shift
mkdir -p /tmp/kept20/sh || exit 1
sed "s#/tmp/legpass19#/tmp/kept20#g; s#\$(dirname \"\$0\")#$D#g" "$D/$S" > /tmp/kept20/sh/$S
case "$S" in
  *.py) /usr/bin/python3 /tmp/kept20/sh/$S "$@" ;;
  *) sh /tmp/kept20/sh/$S "$@" ;;
esac
