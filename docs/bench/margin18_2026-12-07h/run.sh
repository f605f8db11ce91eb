#!/bin/sh
# usage: run.sh GAIT LEVEL CASE: margin16's set.sh (by path) with env.sh's environment, its log
# moved into this folder's logs/ (set.sh writes it into ../margin16_2026-12-07g/logs/).
# Resumable: a log here with its rc line is skipped.
cd "$(dirname "$0")"
. ./env.sh
tag=$1_$2_$3
if [ -f "logs/$tag.log" ] && grep -q '^rc ' "logs/$tag.log"; then exit 0; fi
sh ../margin16_2026-12-07g/set.sh "$1" "$2" "$3"
mv "../margin16_2026-12-07g/logs/$tag.log" "logs/$tag.log"
