#!/usr/bin/env python3
"""check_docs.py: check the manual's pages (README.md, docs/**/*.md, fem/README.md).

    /usr/bin/python3 tools/check_docs.py [--root DIR] [--max-readme-lines 400]

Checks, and prints one line `<file>:<line>: <cause>` per problem (exit status 1 if any):
  - every relative Markdown link or image target exists in the repository (links starting
    with http:, https:, mailto: are not followed);
  - every `#anchor` of a link names a heading of its target page (GitHub's slugs: lower case,
    punctuation dropped, spaces to '-');
  - no page cites a path outside the repository (an absolute path under /work/, /tmp/ or
    /home/, or a link that leaves the repository);
  - README.md has at most --max-readme-lines lines (issue 36: the manual stays short).
Recorded logs under docs/bench/ are not checked (they record the commands as they ran).
Uses only the standard library.
"""

import argparse
import os
import re
import sys

LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")
OUTSIDE = re.compile(r"(?<![\w.])/(?:work|tmp|home)/[\w./+-]+")
HEADING = re.compile(r"^(#{1,6})\s+(.*?)\s*#*\s*$")


def slug(title):
    """GitHub's anchor of a heading: lower case, markup and punctuation dropped, spaces -> '-'."""
    t = title.replace("`", "").replace("*", "")
    t = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", t)
    t = t.strip().lower()
    t = re.sub(r"[^\w\- ]", "", t)
    return t.replace(" ", "-")


def anchors(path, cache):
    if path not in cache:
        found, seen, fence = set(), {}, False
        with open(path, encoding="utf-8") as f:
            for line in f:
                if line.startswith("```"):
                    fence = not fence
                    continue
                m = None if fence else HEADING.match(line)
                if m:
                    s = slug(m.group(2))
                    n = seen.get(s, 0)
                    found.add(s if n == 0 else f"{s}-{n}")
                    seen[s] = n + 1
        cache[path] = found
    return cache[path]


def pages(root):
    yield os.path.join(root, "README.md")
    yield os.path.join(root, "fem", "README.md")
    for d, dirs, files in os.walk(os.path.join(root, "docs")):
        dirs[:] = [x for x in dirs if x != "bench"]
        for name in sorted(files):
            if name.endswith(".md"):
                yield os.path.join(d, name)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--root", default=os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    ap.add_argument("--max-readme-lines", type=int, default=400)
    args = ap.parse_args()
    root = os.path.realpath(args.root)
    problems, cache, nlinks = [], {}, 0
    for page in pages(root):
        if not os.path.exists(page):
            continue
        rel = os.path.relpath(page, root)
        fence = False
        with open(page, encoding="utf-8") as f:
            lines = f.read().split("\n")
        for i, line in enumerate(lines, 1):
            if line.startswith("```"):
                fence = not fence
            for m in OUTSIDE.finditer(line):
                problems.append(f"{rel}:{i}: cites a path outside the repository: {m.group(0)}")
            if fence:
                continue
            for m in LINK.finditer(line):
                target = m.group(1)
                if re.match(r"(https?|mailto):", target):
                    continue
                nlinks += 1
                path, _, frag = target.partition("#")
                full = os.path.realpath(os.path.join(os.path.dirname(page), path)) if path else page
                if not (full == root or full.startswith(root + os.sep)):
                    problems.append(f"{rel}:{i}: link leaves the repository: {target}")
                    continue
                if not os.path.exists(full):
                    problems.append(f"{rel}:{i}: link target does not exist: {target}")
                    continue
                if frag and full.endswith(".md") and frag not in anchors(full, cache):
                    problems.append(f"{rel}:{i}: no heading for anchor #{frag} in {path or rel}")
        if rel == "README.md" and len(lines) - 1 > args.max_readme_lines:
            problems.append(f"README.md:{len(lines) - 1}: {len(lines) - 1} lines, more than "
                            f"{args.max_readme_lines}")
    for p in problems:
        print(p, file=sys.stderr)
    print(f"check_docs.py: {nlinks} links checked, {len(problems)} problem(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
