# check_lib.sh: sourced by the shell tests of tools/ (test_study_plots.sh, test_calib_split.sh):
#   cs_checkInit NAME   a work directory $work (removed at exit), $fail = 0
#   check DESCRIPTION COMMAND...   runs COMMAND; on failure prints "FAILED: DESCRIPTION" and
#                                  sets fail=1 (the test exits with it)
cs_checkInit() {
  work=$(mktemp -d "$1.XXXXXX")
  trap 'rm -rf "$work"' EXIT
  fail=0
}
check() {
  local what=$1
  shift
  if ! "$@"; then
    echo "FAILED: $what"
    fail=1
  fi
}
