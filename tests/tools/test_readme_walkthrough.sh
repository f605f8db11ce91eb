#!/usr/bin/env bash
# test_readme_walkthrough.sh: the README's "Your first gait" runs as written.
#
#   bash tests/tools/test_readme_walkthrough.sh CRAWLSIM SOURCE_DIR
#
# Extracts every fenced block whose opening line is exactly "```sh walkthrough" from
# SOURCE_DIR/README.md, in file order, and runs each one with `bash -euo pipefail` in a fresh
# temporary folder laid out as the README assumes (the repository's root after the quick start:
# build/tools/crawlsim is CRAWLSIM, tools/ is SOURCE_DIR/tools). Proves:
#   - the README has walkthrough blocks (none found fails: a test that cannot fail is a defect);
#   - every block exits 0, in order (a failing block is named by its number and first line);
#   - every file a block names with -o / --out exists afterwards and is not empty.
# Prints each block's wall time for the report (no timing assertion: machines are shared).
set -euo pipefail

if [ $# -ne 2 ]; then
  echo "usage: $0 CRAWLSIM SOURCE_DIR" >&2
  exit 2
fi
crawlsim=$(readlink -f "$1")
src=$(readlink -f "$2")
readme="$src/README.md"
[ -x "$crawlsim" ] || { echo "test_readme_walkthrough: $crawlsim: not an executable" >&2; exit 1; }
[ -f "$readme" ] || { echo "test_readme_walkthrough: $readme: missing" >&2; exit 1; }

work=$(mktemp -d "${TMPDIR:-/tmp}/cs_walkthrough.XXXXXX")
keep=0
cleanup() { if [ "$keep" = 0 ]; then rm -rf "$work"; else echo "kept $work" >&2; fi; }
trap cleanup EXIT

# split the README's walkthrough blocks into block_1.sh, block_2.sh, ...
awk -v dir="$work" '
  /^```sh walkthrough[ \t]*$/ { n++; inb = 1; f = sprintf("%s/block_%d.sh", dir, n); next }
  inb && /^```[ \t]*$/ { inb = 0; close(f); next }
  inb { print > f }
  END { if (inb) { print "unterminated walkthrough block " n > "/dev/stderr"; exit 1 } }
' "$readme"
nblock=$(find "$work" -maxdepth 1 -name 'block_*.sh' | wc -l)
if [ "$nblock" -eq 0 ]; then
  echo "test_readme_walkthrough: $readme: no \`\`\`sh walkthrough blocks found" >&2
  exit 1
fi

# the folder the README's commands expect: the repository's root after the quick start
mkdir -p "$work/root/build/tools"
ln -s "$crawlsim" "$work/root/build/tools/crawlsim"
ln -s "$src/tools" "$work/root/tools"

cd "$work/root"
total_start=$(date +%s.%N)
for i in $(seq 1 "$nblock"); do
  block="$work/block_$i.sh"
  first=$(grep -m1 -v '^[[:space:]]*$' "$block" || true)
  start=$(date +%s.%N)
  if ! bash -euo pipefail "$block" > "$work/block_$i.log" 2>&1; then
    echo "test_readme_walkthrough: block $i of $nblock failed: $first" >&2
    tail -n 20 "$work/block_$i.log" >&2
    keep=1
    exit 1
  fi
  end=$(date +%s.%N)
  printf 'block %d of %d ok (%.1f s): %s\n' "$i" "$nblock" "$(awk -v a="$start" -v b="$end" 'BEGIN { print b - a }')" "$first"
  # the files the block says it writes
  for out in $(grep -oE '(^|[[:space:]])(-o|--out)[[:space:]]+[^[:space:]]+' "$block" |
               awk '{print $NF}'); do
    if [ ! -s "$out" ]; then
      echo "test_readme_walkthrough: block $i: $out was not written (or is empty)" >&2
      keep=1
      exit 1
    fi
  done
done
total_end=$(date +%s.%N)
printf 'walkthrough: %d blocks ran as written in %.1f s (load: %s)\n' "$nblock" \
  "$(awk -v a="$total_start" -v b="$total_end" 'BEGIN { print b - a }')" "$(cut -d' ' -f1-3 /proc/loadavg)"
