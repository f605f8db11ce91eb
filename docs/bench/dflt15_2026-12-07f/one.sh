# one.sh (sourced by noise.sh and more.sh; needs H, D, C): one TAG ARGS... runs
# `crawlsim run ARGS --out $D/TAG.h5` at nice 5 into logs/TAG.log (uptime before and after, the
# command, the banner and summary, /usr/bin/time's user CPU and wall, `rc N`); a tag whose log
# has its rc line is skipped (resumable).
one() {
  tag=$1; shift
  if [ -f "$H/logs/$tag.log" ] && grep -q '^rc ' "$H/logs/$tag.log"; then return 0; fi
  { uptime; echo "crawlsim run $* --out $D/$tag.h5"
    /usr/bin/time -f "%U user %S sys %e wall" nice -n 5 "$C" run "$@" --out "$D/$tag.h5"
    echo "rc $?"; uptime; } > "$H/logs/$tag.log" 2>&1
  rm -f "$D/$tag.xdmf"
}
