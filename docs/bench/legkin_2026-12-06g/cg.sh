#!/bin/bash
# cg.sh BIN TAG T SPEC...: ../strainspeed_2026-12-06f/cg.sh (callgrind of bench_strain_driver's
# scene for T simulated seconds, the run alone, one run per SPEC) with its output in $CG_OUT,
# default /work/rom_data/legkin/cg (TAG.SPEC.TT.{cg,log,uptime} and ir_results.txt there)
export CG_OUT=${CG_OUT:-/work/rom_data/legkin/cg}
mkdir -p "$CG_OUT"
exec "$(dirname "$0")/../strainspeed_2026-12-06f/cg.sh" "$@"
