#!/usr/bin/env bash
# test_calib_split.sh: tools/calib_split.py splits the shipped FE mode table into one case file
# per case that `crawlsim calibrate --merge-only` merges back into a table whose report is the
# shipped table's, line for line (the table's path aside): the way to extend a table with new
# cases. A file that is not a mode table is refused with one line naming it, exit status 1.
#   usage: test_calib_split.sh CRAWLSIM SOURCE_DIR
set -u
exe=$1
src=$2
py=/usr/bin/python3
# shellcheck source=check_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/check_lib.sh"
cs_checkInit calib_split
table=$src/robot/calibration_fe_leg_modes.h5
out=$("$py" "$src/tools/calib_split.py" "$table" "$work/cases" 2>&1)
check "split exits 0" test $? -eq 0
n=$(ls "$work/cases" | wc -l)
check "one file per case ($n)" test "$n" -ge 10
check "split says how many" grep -q "wrote $n case files" <<<"$out"
# the shipped cases ran at Newton's 1e-8 and p-max 0.4: the merge needs the same settings
"$exe" calibrate --merge-only --actuator leg --p-max 0.4 --newton-rtol 1e-8 --dir "$work/cases" \
  --out "$work/re.h5" >"$work/merge.txt" 2>&1
check "merge exits 0" test $? -eq 0
check "merge takes every case" grep -q "0 cases run, 0 already done, $n of" "$work/merge.txt"
"$exe" calibrate --report "$table" >"$work/orig.txt" 2>&1
check "report of the shipped table" test $? -eq 0
check "the merged table reports as the shipped one" \
  diff <(sed -n '/^calibration model/,$p' "$work/orig.txt" | sed 1d) \
  <(sed -n '/^calibration model/,$p' "$work/merge.txt" | sed 1d)
# a second split into the same directory keeps what is there
out=$("$py" "$src/tools/calib_split.py" "$table" "$work/cases" 2>&1)
check "a second split writes nothing" grep -q "wrote 0 case files .*($n already there)" <<<"$out"
# not a mode table: one line, exit 1
"$py" "$src/tools/calib_split.py" "$work/merge.txt" "$work/x" >/dev/null 2>"$work/err.txt"
check "refuses a file that is not HDF5" test $? -eq 1
check "the refusal names the file" grep -q "merge.txt: " "$work/err.txt"
check "the refusal is one line" test "$(wc -l <"$work/err.txt")" -eq 1
exit $fail
