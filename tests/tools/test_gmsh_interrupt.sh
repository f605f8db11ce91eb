#!/bin/bash
# Ctrl-C while gmsh meshes (issue 37's signals): the terminal's SIGINT reaches the whole process
# group, gmsh dies of it, and system() had made crawlsim ignore it meanwhile. The case must be
# recorded as interrupted (no case file, exit 130, rerun by --resume), never as a failed case.
# A stand-in gmsh sends SIGINT to its process group, as a Ctrl-C would, so the test is exact in
# time. usage: test_gmsh_interrupt.sh CRAWLSIM
set -u
exe=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cd "$dir" || exit 1
printf '#!/bin/sh\nkill -INT 0\nsleep 5\n' > fakegmsh.sh
chmod +x fakegmsh.sh
printf 'study gi\ncase a bend --model analytic --actuator baseline --chambers 1,2 --p-max 0.1 --p-step 0.1\ncase fe bend --model fe --actuator baseline --set S1=12 --set S2=12 --set S3=12 --set c=3 --set LS12=4 --p-max 0.02 --p-step 0.02 --mesh-size 5\n' > gi.study
setsid bash -c "CS_GMSH=$dir/fakegmsh.sh '$exe' study gi.study --out gi.h5 > out.txt 2>&1; echo \$? > rc.txt"
rc=$(cat rc.txt)
fail=0
[ "$rc" = 130 ] || { echo "FAILED: exit $rc, expected 130"; fail=1; }
grep -q "case fe: interrupted in bend" out.txt || { echo "FAILED: the case is not recorded as interrupted"; fail=1; }
grep -q "1 complete, 0 stopped, 0 failed, 1 missing" out.txt || { echo "FAILED: the table is not 1 complete, 1 missing"; fail=1; }
cat out.txt | tail -3
[ $fail = 0 ] && echo "ok: exit 130, case fe interrupted and pending"
exit $fail
