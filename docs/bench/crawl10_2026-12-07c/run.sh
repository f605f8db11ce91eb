#!/bin/sh
# crawl10's runs: docs/bench/obst10_2026-12-07c/run.sh with this directory for the logs and
# scores (CASE.txt ends with the crawl's decision, `crawl:`, read from the run file) and the
# HDF5 files in /work/rom_data/crawl10. usage: GAIT=c12 run.sh CASE... (README.md)
cd "$(dirname "$0")/../../.."
B=docs/bench/crawl10_2026-12-07c D=${D:-/work/rom_data/crawl10} exec sh docs/bench/obst10_2026-12-07c/run.sh "$@"
