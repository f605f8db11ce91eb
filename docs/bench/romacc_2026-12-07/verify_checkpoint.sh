#!/usr/bin/env bash
# rom check --checkpoint: a ray checked whole with checkpoints, then resumed from its checkpoint
# after K states (a copy of that one file alone): the last checkpoint's reduced state, predictor
# history and element states must be the whole run's bit for bit (every line but "measured",
# the CPU and wall seconds), and so must the printed state lines. From the repository root after
# a Release build. Usage: verify_checkpoint.sh WORKDIR SNAPDIR LEG.h5 "K ..." [--set ...]
# (the logs beside this script: the short leg's SNAPDIR with the 4-mode leg_o12.h5 (ckpt_short_*:
# romfibre's copy; verify_checkpoint_short.log: romlock's, this script) and
# --set S1=15 --set S2=15 --set S3=15, K = 1 2 3; the real leg's data/rom/leg_l8 rays with
# romcontact's b10 leg_tol1e-2.h5 (n = 96 + 48 mixed, ECSW), K = 3)
set -euo pipefail
W=$1 SNAP=$2 LEG=$3 KS=$4
shift 4
CS=${CS:-$PWD/build/tools/crawlsim}
mkdir -p "$W"
cd "$W"
args=(rom check --snapshots "$SNAP" --leg-file "$LEG" --ray T_H4 --actuator leg "$@")
rm -rf full
nice -n 19 "$CS" "${args[@]}" --checkpoint full > full.log
last=$(ls full | sed -n 's/^T_H4\.\([0-9]*\)\.ckpt$/\1/p' | sort -n | tail -1)
fails=0
for k in $KS; do
  rm -rf "r$k" && mkdir "r$k" && cp "full/T_H4.$k.ckpt" "r$k/"
  nice -n 19 "$CS" "${args[@]}" --checkpoint "r$k" > "r$k.log"
  if cmp -s <(grep -v '^measured' "full/T_H4.$last.ckpt") <(grep -v '^measured' "r$k/T_H4.$last.ckpt") &&
     cmp -s <(grep '^  T_H4' full.log) <(grep '^  T_H4' "r$k.log"); then
    echo "resumed after $k of $last states: bit for bit"
  else
    echo "resumed after $k of $last states: DIFFERS"; fails=1
  fi
done
exit $fails
