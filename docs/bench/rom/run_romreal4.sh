#!/usr/bin/env bash
# Session romreal, fourth (docs/notes/rom.md, "The real leg with the fibre field"): the real
# leg's basis with the mixed fibre field of branch romlock, held out, every element kept.
# From the repository root after a Release build. Usage:
#   run_romreal4.sh OUT STAGE ...
# OUT/snap holds mesh.h5, the training rays and the held-out T_H4, T_S2 (copies of
# data/rom/leg_l8, or of finished rays of the production); stages, in order:
#   legfile      a leg file of a 4-mode basis, for its fibre elements only (rom_basis.py
#                --fibres reads them; the leg file refuses a fibre basis)    -> OUT/legf/leg.h5
#   basis        N POD modes + quarter turns, M pressure modes split at the real leg's
#                connectors (x3 = S1 + LS12/2 = 54 mm, S1 + LS12 + S2 + LS23/2 = 112 mm),
#                supremizers, every fibre strain mode of the training (strains and stresses
#                of the FE states)                                           -> OUT/b<N>_f.h5
#   basis-CFG    (branch romfib) the same span's variants, CFG one of
#                  fs<K>        K fibre modes of the training split per segment at the
#                               connectors (3 K modes; romlock's f32s), M pressure modes as basis
#                  fs<K>m<MM>   the same with MM pressure modes split per segment (3 MM)
#                  fs<K>g<MM>   the same with MM global pressure modes (no split)
#                                                                            -> OUT/b<N>_CFG.h5
#   basis-v13f<K>  (sixth session) V the POD of the thirteen rays of the b13 basis only (N modes,
#                their quarter turns), M pressure modes split and the K largest fibre modes of
#                every training ray (--v-rays): the 13 rays' span with the 25 rays' P and Qf
#                (P and Qf those of `basis` + `trunc-f<K>`; the supremizers follow P)
#                                                                            -> OUT/b<N>_v13f<K>.h5
#   basis-v13f<K>m<MM>  (seventh session) the same with MM pressure modes split per segment
#                (3 MM) instead of M                                         -> OUT/b<N>_v13f<K>m<MM>.h5
#   trunc-f<K>   the `basis` stage's file with its first K fibre modes only (global, the K
#                largest of the training's W-weighted POD: what --fibre-modes K writes, in seconds;
#                V and P bit for bit)                                        -> OUT/b<N>_f<K>.h5
#   legfile-CFG  the every-element leg file of OUT/b<N>_CFG.h5 (rom leg-file: the set-up of
#                gmsh and the chamber forms paid once)                       -> OUT/leg_CFG.h5
#   checkleg-CFG-RAY  rom check of RAY on that leg file (set-up seconds)    -> OUT/checkleg_<CFG>_<RAY>.log
#   rays-rs      (session romacc, 2026-12-07) the sparse random training rays RS1-RS6 (per segment
#                a level, chambers vented at random: the family of T_S2's and T_R's vented
#                chambers between loaded ones) on the real leg, one FE process on one thread,
#                resumable ray by ray, into OUT/snap_rs (its own mesh.h5: OUT/snap may hold hard
#                links to other folders' files, and the production rewrites mesh.h5); then hard
#                linked into OUT/snap once both mesh.h5 hold the same mesh (every later `basis`
#                stage trains on them)                                    -> OUT/snap/RS<k>.h5
#   link-rs      (session romrs, 2026-12-07) the same mesh check and links for the RS rays
#                finished so far (a production stopped between rays: the basis on part of
#                the family; rays-rs resumes the rest)                    -> OUT/snap/RS<k>.h5
#   rays-sq, link-sq  (session rom10, 2026-12-07) the same for the squeezed-chamber rays SQ1-SQ6
#                (per segment a dominant chamber, the opposite vented, the flanks light or
#                unequal: fem_rom_snap.c), into OUT/snap_sq; SQ="SQ1 SQ2 ..." picks and orders
#                them (default all six)                                   -> OUT/snap/SQ<k>.h5
#   base         the same file without its fibre basis (Qf, mf): the same span with the FE's
#                fibres, for the locking's share                             -> OUT/b<N>_base.h5
#   project      the held-out states' best projection onto the span (tools/rom_project.py)
#                                                                            -> OUT/b<N>_f_projection.log
#   energy       what the span charges them: bulk in span(P), fibres with and without span(Q)
#                (romlock_span_energy.py)                                   -> OUT/b<N>_f_span_energy.log
#   check-CFG-RAY   rom check of RAY on OUT/b<N>_CFG.h5 (CFG f or base), every element kept
#                                                                            -> OUT/check_<CFG>_<RAY>.log
# Each stage is skipped when its output is complete (resumable per ray: a check is one ray, as
# every reduced Newton iteration with every element costs about a minute of wall time under load);
# since 2026-12-07 a check resumes within its ray too, after its last state (rom check
# --checkpoint: OUT/ckpt_leg_CFG or OUT/ckpt_b<N>_CFG; delete it to check afresh).
# Environment: CS the crawlsim binary, N (96), M (16), NICE (5).
set -euo pipefail
OUT=$(readlink -f "$1")
shift
CS=${CS:-$PWD/build/tools/crawlsim}
N=${N:-96}
M=${M:-16}
NICE=${NICE:-5}
PY=/usr/bin/python3
SNAP=$OUT/snap
export OMP_WAIT_POLICY=PASSIVE OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
T=(/usr/bin/time -f '%e s wall, %U s user, %M kB resident')
mkdir -p "$OUT/legf"
for stage in "$@"; do
  echo "== $stage ($(date -u +%H:%M:%S), load $(cut -d' ' -f1-3 /proc/loadavg))"
  case $stage in
    legfile)
      [ -s "$OUT/legf/leg.h5" ] || {
        "${T[@]}" nice -n "$NICE" $PY tools/rom_basis.py "$SNAP" --n 4 --out "$OUT/legf/b4.h5" \
          > "$OUT/legf/b4_basis.log" 2>&1
        "${T[@]}" nice -n "$NICE" "$CS" rom leg-file --basis "$OUT/legf/b4.h5" \
          --out "$OUT/legf/leg.h5" --work "$OUT/legf" --actuator leg > "$OUT/legf/leg.log" 2>&1
      } ;;
    basis)
      [ -s "$OUT/b${N}_f.h5" ] ||
        "${T[@]}" nice -n "$NICE" $PY tools/rom_basis.py "$SNAP" --turns --n "$N" --m "$M" \
          --p-split 54,112 --mixed --fibre-modes 100000 --fibres "$OUT/legf/leg.h5" \
          --out "$OUT/b${N}_f.h5" > "$OUT/b${N}_f_basis.log" 2>&1 ;;
    basis-v13f*)
      cfg=${stage#basis-}
      [[ $cfg =~ ^v13f([0-9]+)(m([0-9]+))?$ ]] ||
        { echo "run_romreal4.sh: stage $stage: CFG is v13f<K> or v13f<K>m<MM>" >&2; exit 2; }
      k=${BASH_REMATCH[1]}
      pm=${BASH_REMATCH[3]:-$M}
      [ -s "$OUT/b${N}_${cfg}.h5" ] ||
        "${T[@]}" nice -n "$NICE" $PY tools/rom_basis.py "$SNAP" --turns --n "$N" --m "$pm" \
          --p-split 54,112 --mixed --fibre-modes "$k" --fibres "$OUT/legf/leg.h5" \
          --v-rays O12,S,O1,R1,Z,II1only,R2,O13,Fx,Gx,O1O234r05,O12O3r05,O124 \
          --out "$OUT/b${N}_${cfg}.h5" > "$OUT/b${N}_${cfg}_basis.log" 2>&1 ;;
    basis-*)
      cfg=${stage#basis-}
      [[ $cfg =~ ^fs([0-9]+)(([mg])([0-9]+))?$ ]] ||
        { echo "run_romreal4.sh: stage $stage: CFG is fs<K>, fs<K>m<MM> or fs<K>g<MM>" >&2; exit 2; }
      k=${BASH_REMATCH[1]}
      pk=${BASH_REMATCH[3]:-m}
      pm=${BASH_REMATCH[4]:-$M}
      psplit=(--p-split 54,112)
      [ "$pk" = g ] && psplit=()
      [ -s "$OUT/b${N}_${cfg}.h5" ] ||
        "${T[@]}" nice -n "$NICE" $PY tools/rom_basis.py "$SNAP" --turns --n "$N" --m "$pm" \
          "${psplit[@]}" --mixed --fibre-modes "$k" --f-split 54,112 --fibres "$OUT/legf/leg.h5" \
          --out "$OUT/b${N}_${cfg}.h5" > "$OUT/b${N}_${cfg}_basis.log" 2>&1 ;;
    trunc-f*)
      k=${stage#trunc-f}
      [ -s "$OUT/b${N}_f${k}.h5" ] ||
        $PY - "$OUT/b${N}_f.h5" "$OUT/b${N}_f${k}.h5" "$k" <<'PYEOF'
import os
import sys
import h5py
# Qf's columns are the POD's in decreasing order (rom_basis.py fibre_basis): the first K are
# the basis of --fibre-modes K; everything else copied bit for bit
k = int(sys.argv[3])
with h5py.File(sys.argv[1], "r") as src, h5py.File(sys.argv[2] + ".tmp", "w") as dst:
    if not 0 < k <= src["Qf"].shape[1]:
        sys.exit(f"run_romreal4.sh: trunc-f{k}: {sys.argv[1]} has {src['Qf'].shape[1]} fibre modes")
    for key, v in src.attrs.items():
        dst.attrs[key] = v
    dst.attrs["mf"] = k
    for key in src:
        if key != "Qf":
            src.copy(key, dst)
    dst.create_dataset("Qf", data=src["Qf"][:, :k])
os.replace(sys.argv[2] + ".tmp", sys.argv[2])
PYEOF
      ;;
    legfile-*)
      cfg=${stage#legfile-}
      [ -s "$OUT/leg_${cfg}.h5" ] ||
        (mkdir -p "$OUT/legwork" && "${T[@]}" nice -n "$NICE" "$CS" rom leg-file \
          --basis "$OUT/b${N}_${cfg}.h5" --out "$OUT/leg_${cfg}.h5" --work "$OUT/legwork" \
          --actuator leg > "$OUT/leg_${cfg}.log" 2>&1) ;;
    checkleg-*)
      cfg=${stage#checkleg-}
      ray=${cfg##*-}
      cfg=${cfg%-*}
      log=$OUT/checkleg_${cfg}_${ray}.log
      grep -qs 'rays checked' "$log" ||
        (cd "$OUT" && "${T[@]}" nice -n "$NICE" stdbuf -oL "$CS" rom check --snapshots "$SNAP" \
          --leg-file "$OUT/leg_${cfg}.h5" --ray "$ray" --actuator leg \
          --checkpoint "$OUT/ckpt_leg_${cfg}" > "$log" 2>&1) ;;
    rays-rs|rays-sq)
      fam=${stage#rays-}
      if [ "$fam" = rs ]; then rs=(RS1 RS2 RS3 RS4 RS5 RS6); else read -ra rs <<< "${SQ:-SQ1 SQ2 SQ3 SQ4 SQ5 SQ6}"; fi
      mkdir -p "$OUT/snap_$fam"
      "${T[@]}" nice -n "$NICE" "$CS" rom snapshots --out "$OUT/snap_$fam" --mesh-size 8 \
        --threads 1 --actuator leg "${rs[@]/#/--ray=}" >> "$OUT/snap_$fam/production.log" 2>&1
      ;&
    link-rs|link-sq)
      fam=${stage#*-}
      if [ "$fam" = rs ]; then rs=(RS1 RS2 RS3 RS4 RS5 RS6); else rs=(SQ1 SQ2 SQ3 SQ4 SQ5 SQ6); fi
      $PY - "$SNAP/mesh.h5" "$OUT/snap_$fam/mesh.h5" <<'PYEOF'
import sys
import h5py
import numpy as np
# the rays are displacements on the mesh's dofs: the same nodes, elements, faces and clamp, or
# they cannot join the training (the files' bytes differ by HDF5's object times)
with h5py.File(sys.argv[1], "r") as a, h5py.File(sys.argv[2], "r") as b:
    for key in ("x", "tet", "face", "face_tag", "fixed", "tip_unit"):
        if a[key].shape != b[key].shape or not np.array_equal(a[key][...], b[key][...]):
            sys.exit(f"run_romreal4.sh: rays: {sys.argv[2]}: /{key} is not that of {sys.argv[1]}")
PYEOF
      # a ray's file appears when the ray is finished (cmd_rom.c renames it from its part file)
      for r in "${rs[@]}"; do
        [ ! -s "$OUT/snap_$fam/$r.h5" ] || ln -f "$OUT/snap_$fam/$r.h5" "$SNAP/$r.h5"
      done ;;
    base)
      [ -s "$OUT/b${N}_base.h5" ] ||
        $PY - "$OUT/b${N}_f.h5" "$OUT/b${N}_base.h5" <<'PYEOF'
import os
import sys
import h5py
# every dataset and attribute but the fibre basis: bit-identical V, P, snapshots
with h5py.File(sys.argv[1], "r") as src, h5py.File(sys.argv[2] + ".tmp", "w") as dst:
    for k, v in src.attrs.items():
        if k != "mf":
            dst.attrs[k] = v
    for k in src:
        if k != "Qf":
            src.copy(k, dst)
os.replace(sys.argv[2] + ".tmp", sys.argv[2])
PYEOF
      ;;
    project)
      [ -s "$OUT/b${N}_f_projection.log" ] ||
        "${T[@]}" nice -n "$NICE" $PY tools/rom_project.py "$SNAP" "$OUT/b${N}_f.h5" \
          > "$OUT/b${N}_f_projection.log" 2>&1 ;;
    energy)
      [ -s "$OUT/b${N}_f_span_energy.log" ] ||
        "${T[@]}" nice -n "$NICE" $PY docs/bench/rom/romlock_span_energy.py "$SNAP" \
          "$OUT/b${N}_f.h5" "$OUT/legf/leg.h5" --ray T_H4 --ray T_S2 \
          > "$OUT/b${N}_f_span_energy.log" 2>&1 ;;
    check-*)
      cfg=${stage#check-}
      ray=${cfg#*-}
      cfg=${cfg%%-*}
      log=$OUT/check_${cfg}_${ray}.log
      grep -qs 'rays checked' "$log" ||
        (cd "$OUT" && "${T[@]}" nice -n "$NICE" stdbuf -oL "$CS" rom check --snapshots "$SNAP" \
          --basis "$OUT/b${N}_${cfg}.h5" --ray "$ray" --actuator leg \
          --checkpoint "$OUT/ckpt_b${N}_${cfg}" > "$log" 2>&1) ;;
    *) echo "run_romreal4.sh: unknown stage $stage" >&2; exit 2 ;;
  esac
done
echo "== done ($(date -u +%H:%M:%S), load $(cut -d' ' -f1-3 /proc/loadavg))"
