#!/bin/sh
# crun.sh TAG ARGS...: ../levels9_2026-12-07b/crun.sh (one `crawlsim run ARGS --quiet --out
# $D/TAG.h5`, nice 5, its output, CPU and uptime in $LOGS/TAG.log; resumable) with this
# branch's places: D /tmp/bdf13/runs, CRAWLSIM /tmp/bdf13/crawlsim (a copy of this branch's
# build), LOGS logs/ beside this script.
H=$(dirname "$0")
export D=${D:-/tmp/bdf13/runs} CRAWLSIM=${CRAWLSIM:-/tmp/bdf13/crawlsim} LOGS=${LOGS:-$H/logs}
exec "$H/../levels9_2026-12-07b/crun.sh" "$@"
