#!/usr/bin/env bash
# test_no_outside_citations.sh: the repository stands alone. No source, script, build file or
# page cites a file outside it: the design, reference and style notes the code relies on are
# docs/design.md, docs/reference.md and docs/style.md; nothing names a path under /work/,
# /home/ or ../shared/. Recorded measurements (docs/bench/, *.log, *.csv) keep the commands as
# they ran and are not checked.
# Usage: test_no_outside_citations.sh SOURCE_DIR
set -uo pipefail
root=${1:?usage: test_no_outside_citations.sh SOURCE_DIR}
cd "$root" || exit 2
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  files=$(git ls-files)
else
  files=$(find . -type f -not -path './.git/*' -not -path './build*' | sed 's#^\./##')
fi
bad=0
while IFS= read -r f; do
  case "$f" in
    docs/bench/*|*.log|*.csv|*.h5|*.png|*.gif|*.msh) continue ;;
    tests/tools/test_no_outside_citations.sh) continue ;; # it names the patterns it looks for
  esac
  [ -f "$f" ] || continue
  # a bare DESIGN.md / REFERENCE.md / STYLE.md is a citation of the notes outside the repository
  hits=$(grep -nP '(?<![\w/.])(DESIGN|REFERENCE|STYLE)\.md|\.\./shared/|(?<![\w.])/(work|home)/[\w.-]' "$f" 2>/dev/null)
  if [ -n "$hits" ]; then
    while IFS= read -r h; do echo "$f:$h"; done <<<"$hits"
    bad=1
  fi
done <<<"$files"
if [ "$bad" -ne 0 ]; then
  echo "test_no_outside_citations: the lines above cite files outside the repository" >&2
  exit 1
fi
echo "test_no_outside_citations: $(wc -l <<<"$files") files, no citation outside the repository"
