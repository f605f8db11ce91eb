#!/bin/sh
# usage: gen.sh NAME [obstacle_gait.py options]: NAME.gait here, designed with its footholds
# (tools/obstacle_gait.py --foothold-out, rule 15) into runs/NAME.csv, runs/NAME.foothold and
# runs/NAME.foothold.d/ on the mission's table; CRAWLSIM: the binary
set -e
cd "$(dirname "$0")/../../.."
B=docs/bench/obstacle_foothold_2026-12-06
CS=${CRAWLSIM:-build/tools/crawlsim}
n=$1; shift
mkdir -p runs
nice -n 10 /usr/bin/python3 tools/obstacle_gait.py -o $B/$n.gait --crawlsim $CS --foothold-out runs/$n --design-cache runs/design_cache "$@" > $B/$n.design.log 2>&1
cp runs/$n.foothold $B/$n.foothold
echo "$n: $(grep -c '^candidate' runs/$n.foothold) candidates in $(grep -c '^foothold' runs/$n.foothold) footholds"
