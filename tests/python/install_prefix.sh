#!/usr/bin/env bash
# install_prefix.sh CMAKE BUILD_DIR PREFIX: install the build into PREFIX (emptied first) as a
# user would (`cmake --install BUILD --prefix ~/.local`) and write PREFIX/pythonpath.txt, the
# directory the crawlsim package went to (found, not assumed: that is what is tested).
set -euo pipefail
cmake=$1 build=$2 prefix=$3
rm -rf "$prefix"
"$cmake" --install "$build" --prefix "$prefix" >"$prefix.log" 2>&1 || {
  cat "$prefix.log" >&2; echo "install_prefix: cmake --install failed" >&2; exit 1; }
init=$(find "$prefix" -path '*/crawlsim/__init__.py' | head -n 1)
[ -n "$init" ] || { echo "install_prefix: no crawlsim/__init__.py under $prefix" >&2; exit 1; }
[ -f "$(dirname "$init")/_paths.py" ] || { echo "install_prefix: no _paths.py beside $init" >&2; exit 1; }
dirname "$(dirname "$init")" >"$prefix/pythonpath.txt"
echo "install_prefix: package in $(cat "$prefix/pythonpath.txt")"
