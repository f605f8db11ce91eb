#!/bin/sh
# usage: gen.sh NAME [obstacle_gait.py options]: NAME.gait here, designed with its footholds
# (tools/obstacle_gait.py --foothold-out, rule 15) into runs/NAME.csv, runs/NAME.foothold and
# runs/NAME.foothold.d/ on the mission's table (runs/ is not kept: this command regenerates
# it, one `crawlsim gait design` per candidate, cached by statements in runs/design_cache);
# NAME.foothold here is a copy of the index; CRAWLSIM: the binary
set -e
cd "$(dirname "$0")/../../.."
B=docs/bench/obstacle_2026-12-06c
CS=${CRAWLSIM:-build/tools/crawlsim}
n=$1; shift
mkdir -p runs
nice -n 5 /usr/bin/python3 tools/obstacle_gait.py -o $B/$n.gait --crawlsim $CS --foothold-out runs/$n --design-cache runs/design_cache "$@"
cp runs/$n.foothold $B/$n.foothold
echo "$n: $(grep -c '^candidate' runs/$n.foothold) candidates in $(grep -c '^foothold' runs/$n.foothold) footholds"
