#!/bin/sh
# run_tracks.sh T SCENE H5DIR SPEC...: T s of SCENE (flat-road or obstacle) for each strain
# basis SPEC (bench_strain_driver's LEVEL:LINKS:DT:ORDER:TOL:ACTIVE:FRIC:TRUST:KEEP:JOINTS:SHEAR:SUB),
# one run after the other, each in its own process, tracks kept in H5DIR; from build/tests/core
# with CS_SOURCE_DIR the worktree. Compare with ../onepass_2026-12-06/tracks.py.
T=$1; S=$2; export CS_BENCH_KEEP=$3; shift 3
mkdir -p "$CS_BENCH_KEEP"
uptime
for SPEC in "$@"; do
  CS_BENCH_SCENE=$S nice -n 5 ./bench_strain_driver "$T" "$SPEC"
  uptime
done
