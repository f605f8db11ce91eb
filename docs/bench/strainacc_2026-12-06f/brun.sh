#!/bin/sh
# brun.sh TAG SCENE T SPEC [VAR=VALUE...]: one bench_strain_driver run (SPEC as its usage:
# LEVEL:LINKS:DT:ORDER:TOL:ACTIVE:FRIC:TRUST:KEEP:JOINTS:SHEAR:SUB) of T s of SCENE (flat-road,
# obstacle), its track kept in $D/TAG/ (D default /work/rom_data/strainacc), its output in
# $D/TAG.log; from build/tests/core with CS_SOURCE_DIR the worktree. Extra VAR=VALUE go to the
# environment (CS_BENCH_PTOL=0.1: pneumatic tolerances x 0.1).
TAG=$1; S=$2; T=$3; SPEC=$4; shift 4
D=${D:-/work/rom_data/strainacc}
mkdir -p "$D/$TAG"
{ uptime; env "$@" CS_BENCH_KEEP="$D/$TAG" CS_BENCH_SCENE="$S" nice -n 5 ./bench_strain_driver "$T" "$SPEC"; uptime; } > "$D/$TAG.log" 2>&1
echo "$TAG rc $?"
