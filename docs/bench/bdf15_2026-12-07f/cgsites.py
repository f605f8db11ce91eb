#!/usr/bin/env python3
"""cgsites.py CG FUNC [FUNC ...]: the calls to FUNC (exact name) in a callgrind profile by call
site: the calling function and the source file and line of the call (inlined code keeps its
own file and line in the debug information, so a call made from a static function inlined into
another is still told apart by its line), with the calls and the inclusive instructions they
cost. Reads callgrind's compressed names and relative positions (--compress-strings,
--compress-pos)."""
import re, sys
from collections import defaultdict


def sites(path, funcs):
    names = {"fn": {}, "fl": {}}
    fn = fl = cur_file = None
    line = 0
    pending = None  # (callee, calls)
    out = defaultdict(lambda: [0, 0])
    with open(path) as f:
        for raw in f:
            s = raw.rstrip("\n")
            m = re.match(r"(fn|cfn|cfi|cfl|fl|fi|fe)=\((\d+)\)(?: (.*))?$", s)
            if m:
                kind, ident, name = m.groups()
                table = names["fn"] if kind in ("fn", "cfn") else names["fl"]
                if name:
                    table[ident] = name
                name = table.get(ident, "?")
                if kind == "fn":
                    fn = name
                elif kind == "fl":
                    fl = cur_file = name
                elif kind in ("fi", "fe"):
                    cur_file = name
                elif kind == "cfn":
                    callee = name
                continue
            m = re.match(r"calls=(\d+)", s)
            if m:
                pending = (callee, int(m.group(1)))
                continue
            if s and (s[0].isdigit() or s[0] in "+-*"):
                tok = s.split()
                p = tok[0]
                if p == "*":
                    pass
                elif p[0] in "+-":
                    line += int(p)
                else:
                    line = int(p)
                if pending:
                    callee, n = pending
                    pending = None
                    if callee in funcs:
                        cost = int(tok[1]) if len(tok) > 1 else 0
                        key = (callee, fn, cur_file.split("/")[-1] if cur_file else "?", line)
                        out[key][0] += n
                        out[key][1] += cost
                continue
            if s.startswith("fn=") or s == "":
                pass
    return out


def main():
    path, funcs = sys.argv[1], set(sys.argv[2:])
    out = sites(path, funcs)
    print("| callee | caller | site (file:line) | calls | inclusive Ir |")
    print("|---|---|---|---|---|")
    for (callee, fn, f, ln), (n, c) in sorted(out.items(), key=lambda kv: (kv[0][0], -kv[1][1])):
        print(f"| {callee} | {fn} | {f}:{ln} | {n} | {c:,} |")


main()
