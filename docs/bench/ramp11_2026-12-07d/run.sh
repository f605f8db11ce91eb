#!/bin/sh
# ramp11's runs: docs/bench/obst10_2026-12-07c/run.sh (with crawl10's `crawl:` line) with this
# directory for the logs and scores and the HDF5 files in /work/rom_data/ramp11 (not kept).
# usage: GAIT=NAME run.sh CASE... (README.md)
cd "$(dirname "$0")/../../.."
B=docs/bench/ramp11_2026-12-07d D=${D:-/work/rom_data/ramp11} exec sh docs/bench/obst10_2026-12-07c/run.sh "$@"
