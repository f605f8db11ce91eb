#!/usr/bin/env bash
# Session romacc (docs/notes/rom.md, goal 3): the 0-0.4 MPa bend sweep of the short leg, the full
# FE and `bend --model rom` (its default reduced Newton: a kept tangent with BFGS pairs,
# fem_rom_act.h) one after the other in one run, then bench_rom_sweep with Newton and BFGS after
# one set-up: run_romfast_sweep.sh with these settings. Arguments OUT, BASIS, WEIGHTS; CS and
# BENCH as there. (The logged run, romacc_sweep_timed.log, ran the rom before the FE's set-up
# step; the commands are the same.)
BENCH_ARGS="0 0.9b8 0.9b4 0.99b16" exec bash "$(dirname "$0")/run_romfast_sweep.sh" "$@"
