#!/usr/bin/env bash
# Session romecsw (docs/notes/rom.md, "ECSW on the real leg's fibre basis"): the hyper-reduction
# of the real leg's best reduced model (13 rays' V, 96 POD + 72 supremizers, m = 72 split,
# mf = 104), its held-out check and the timed 0-0.4 MPa sweep against the full FE. From the
# repository root after a Release build. Usage:
#   run_romecsw.sh OUT STAGE ...
# OUT is a folder of run_romreal4.sh (N=96) that holds OUT/snap (data/rom/leg_l8's rays),
# OUT/b96_CFG.h5 and its every-element leg file OUT/leg_CFG.h5 (CFG, default v13f104m24:
# `N=96 bash docs/bench/rom/run_romreal4.sh OUT legfile basis-v13f104m24 legfile-v13f104m24`,
# 112 + 270 s of CPU). Stages, each skipped when its output is complete:
#   matrix-SET     rom ecsw-matrix of one set (tet or fibre) on the training states of the 13
#                  rays V was made of (romecsw_subset_training.py: 208 of the basis' 400 with the
#                  quarter turns; the other rays' states project badly onto V, one inverts an
#                  element), every EVERY_TET-th (7: 30 states) or EVERY_FIB-th (14: 15 states; a
#                  fibre state's rows are n + 4 mf = 584 against a Tet10's n + m = 240), the model
#                  read from the every-element leg file (no gmsh)  -> OUT/ecsw_CFG/A_<SET>.h5
#   fit-SET TOL... rom_ecsw.py on one set (tet or fibre), one pass to the smallest TOL, a
#                  weights file per TOL (the fibre fit without G's entries: --no-projection,
#                  as session romfibre; FIBPROJ=1 keeps them)      -> OUT/ecsw_CFG/w<SET>_tol<TOL>.h5
#   leg-T<TT>-F<FT>  the Tet10 weights of TT with the fibres' of FT (romsweep_combine_weights.py;
#                  FT "all": every fibre kept at weight 1),
#                  written into a leg file from the every-element one (rom leg-file --leg-file:
#                  seconds, no gmsh)                               -> OUT/ecsw_CFG/leg_t<TT>_f<FT>.h5
#   check-T<TT>-F<FT>-RAY  rom check of RAY on that leg file, resumable after every state
#                                                                  -> OUT/ecsw_CFG/check_t<TT>_f<FT>_<RAY>.log
#   sweep LEG...   the timed run: bend --model fe on the real leg's mesh (--threads 1), then
#                  bend --model rom --rom-file on each LEG (a path, or t<TT>_f<FT> for the leg
#                  file above, or "all" for OUT/leg_CFG.h5), each under /usr/bin/time, the load
#                  between; romsweep_compare.py's table against the FE  -> OUT/sweep_<K>/
# TT, FT as Python's %g writes them (0.01, 0.003). Environment: CS the crawlsim binary, CFG,
# EVERY_TET, EVERY_FIB, NICE (5; the sweep runs at NICE too, both models alike).
set -euo pipefail
OUT=$(readlink -f "$1")
shift
CS=${CS:-$PWD/build/tools/crawlsim}
CFG=${CFG:-v13f104m24}
EVERY_TET=${EVERY_TET:-7}
EVERY_FIB=${EVERY_FIB:-14}
NICE=${NICE:-5}
PY=/usr/bin/python3
HERE=$(dirname "$0")
E=$OUT/ecsw_$CFG
LEGALL=$OUT/leg_$CFG.h5
export OMP_WAIT_POLICY=PASSIVE OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
T=(/usr/bin/time -f '%e s wall, %U s user, %S s system, %M kB resident')
mkdir -p "$E"
legname() { # t<TT>_f<FT> or all or a path -> the leg file
  case $1 in
    all) echo "$LEGALL" ;;
    t*_f*) echo "$E/leg_$1.h5" ;;
    *) readlink -f "$1" ;;
  esac
}
while [ $# -gt 0 ]; do
  stage=$1
  shift
  echo "== $stage ($(date -u +%H:%M:%S), load $(cut -d' ' -f1-3 /proc/loadavg))"
  case $stage in
    matrix-tet|matrix-fibre)
      set_=${stage#matrix-}
      ev=$EVERY_TET
      [ "$set_" = fibre ] && ev=$EVERY_FIB
      [ -s "$E/A_$set_.h5" ] || {
        $PY "$HERE/romecsw_subset_training.py" "$OUT/b96_$CFG.h5" "$E/b96_${CFG}_$set_.h5" \
          --every "$ev"
        "${T[@]}" nice -n "$NICE" "$CS" rom ecsw-matrix --basis "$E/b96_${CFG}_$set_.h5" \
          --leg-file "$LEGALL" --only "$set_" --out "$E/A_$set_.h5.tmp" --actuator leg \
          > "$E/A_$set_.log" 2>&1
        mv "$E/A_$set_.h5.tmp" "$E/A_$set_.h5"
      } ;;
    fit-tet|fit-fibre)
      set_=${stage#fit-}
      tv=()
      while [ $# -gt 0 ] && [[ $1 =~ ^[0-9.eE+-]+$ ]]; do tv+=("$(printf '%g' "$1")"); shift; done
      [ ${#tv[@]} -gt 0 ] || { echo "run_romecsw.sh: $stage needs TOL..." >&2; exit 2; }
      tols=()
      for t in "${tv[@]}"; do tols+=(--tol "$t"); done
      extra=()
      [ "$set_" = fibre ] && [ "${FIBPROJ:-0}" != 1 ] && extra=(--no-projection)
      # one pass for every TOL, the smallest last; done when the smallest's file exists
      small=$(printf '%s\n' "${tv[@]}" | sort -g | head -1)
      if [ ! -s "$E/w${set_}_tol$small.h5" ]; then
        "${T[@]}" nice -n "$NICE" $PY tools/rom_ecsw.py "$E/A_$set_.h5" --set "$set_" "${extra[@]}" \
          --out "$E/w${set_}.h5" "${tols[@]}" > "$E/fit_${set_}_$small.log" 2>&1
        # a single TOL is written to w<SET>.h5: named by its tolerance as the others
        [ ${#tv[@]} -eq 1 ] && mv "$E/w${set_}.h5" "$E/w${set_}_tol$small.h5"
      fi ;;
    leg-*)
      [[ $stage =~ ^leg-T([0-9.e-]+)-F([0-9.e-]+|all)$ ]] ||
        { echo "run_romecsw.sh: stage $stage: leg-T<TT>-F<FT>" >&2; exit 2; }
      tt=${BASH_REMATCH[1]} ft=${BASH_REMATCH[2]}
      leg=$E/leg_t${tt}_f${ft}.h5
      [ -s "$leg" ] || {
        w=$E/w_t${tt}_f${ft}.h5
        if [ "$ft" = all ]; then
          w=$E/wtet_tol$tt.h5 # a weights file without a fibre set keeps every fibre at 1
        else
          $PY "$HERE/romsweep_combine_weights.py" "$E/wtet_tol$tt.h5" "$E/wfibre_tol$ft.h5" "$w"
        fi
        "${T[@]}" nice -n "$NICE" "$CS" rom leg-file --leg-file "$LEGALL" --weights "$w" \
          --out "$leg.tmp" --actuator leg > "$E/leg_t${tt}_f${ft}.log" 2>&1
        mv "$leg.tmp" "$leg"
      } ;;
    check-*)
      [[ $stage =~ ^check-T([0-9.e-]+)-F([0-9.e-]+|all)-(.+)$ ]] ||
        { echo "run_romecsw.sh: stage $stage: check-T<TT>-F<FT>-RAY" >&2; exit 2; }
      tt=${BASH_REMATCH[1]} ft=${BASH_REMATCH[2]} ray=${BASH_REMATCH[3]}
      log=$E/check_t${tt}_f${ft}_${ray}.log
      grep -qs 'rays checked' "$log" ||
        (cd "$E" && "${T[@]}" nice -n "$NICE" stdbuf -oL "$CS" rom check --snapshots "$OUT/snap" \
          --leg-file "$E/leg_t${tt}_f${ft}.h5" --ray "$ray" --actuator leg \
          --checkpoint "$E/ckpt_t${tt}_f${ft}" > "$log" 2>&1) ;;
    sweep)
      legs=("$@")
      set --
      k=1
      while [ -e "$OUT/sweep_$k" ]; do k=$((k + 1)); done
      S=$OUT/sweep_$k
      mkdir -p "$S"
      EX=(--actuator leg --chambers 1,2 --p-max 0.4 --p-step 0.05)
      {
        echo "== load before the FE: $(uptime)"
        /usr/bin/time -f '== fe: %e s wall, %U s user, %S s system, %M kB' nice -n "$NICE" \
          "$CS" bend --model fe --mesh-symmetric 1 --mesh-size 8 --threads 1 "${EX[@]}" \
          --out "$S/bend_fe.h5" 2>&1
        echo "== load after the FE: $(uptime)"
        files=()
        j=0
        for l in "${legs[@]}"; do
          j=$((j + 1))
          f=$(legname "$l")
          /usr/bin/time -f "== rom $f: %e s wall, %U s user, %S s system, %M kB" nice -n "$NICE" \
            "$CS" bend --model rom --rom-file "$f" "${EX[@]}" --out "$S/bend_rom_$j.h5" 2>&1
          echo "== load after it: $(uptime)"
          files+=("$S/bend_rom_$j.h5")
        done
        $PY "$HERE/romsweep_compare.py" "$S/bend_fe.h5" "$S/bend_fe.h5" "${files[@]}"
      } > "$S/sweep.log" 2>&1
      echo "sweep -> $S/sweep.log" ;;
    *) echo "run_romecsw.sh: unknown stage $stage" >&2; exit 2 ;;
  esac
done
echo "== done ($(date -u +%H:%M:%S), load $(cut -d' ' -f1-3 /proc/loadavg))"
