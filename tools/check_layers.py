#!/usr/bin/env python3
"""check_layers.py: the dependency graph drawn from #includes runs one way (docs/design.md "Rooms").

    /usr/bin/python3 tools/check_layers.py [--root DIR] [--print]

Reads the declared order of the rooms from the ```layers block of DIR/docs/design.md: one room a
line, `ROOM: ROOM ROOM ...`, naming the rooms it may include directly; what those may include it
may include too (the declaration is read as its transitive closure). A room is a folder: a
top folder, or a subfolder of one as a room of its own (robot/rod/ apart from robot/).

Then reads every C source and header (.c, .h) under the top folders (all but tests/ and docs/),
maps each `#include "name"` to the file of the tree that bears that name (the build's include
directories let code include by bare name, so a name is unique in the tree; a name no file of
the tree bears is a system or dependency header and is not an arrow) and draws an arrow from the
including file's room to the included file's room.

Fails (exit status 1, one line `<file>:<line>: <cause>` per problem) on
  - an arrow the declared order does not allow (it runs back up, or sideways between rooms the
    declaration leaves unordered);
  - a circle between rooms (a loop in the declaration itself, or one in the code);
  - a room of the tree that the declaration does not name, or a name borne by two files;
  - no declaration at all.
--print lists the rooms with their arrows (file counts) as the code has them.
Uses only the standard library.
"""

import argparse
import os
import re
import sys

TOP = ("base", "actuator", "core", "fem", "contact", "robot", "gaits", "terrains", "tools")
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')
BLOCK = re.compile(r"^```layers\s*$")


def read_declaration(design):
    """The ```layers block of design.md: {room: [rooms it may include directly]}, with lines."""
    decl, where, inside = {}, {}, False
    with open(design, encoding="utf-8") as f:
        for i, line in enumerate(f, 1):
            if not inside:
                inside = bool(BLOCK.match(line))
                continue
            if line.startswith("```"):
                break
            line = line.split("#", 1)[0].strip()
            if not line:
                continue
            room, _, below = line.partition(":")
            room = room.strip().rstrip("/")
            decl[room] = [r.rstrip("/") for r in below.split()]
            where[room] = i
    return decl, where


def declared_cycle(decl):
    """A loop of the declaration, as a list of rooms, or None."""
    state, stack = {}, []

    def visit(r):
        state[r] = 1
        stack.append(r)
        for b in decl.get(r, []):
            if state.get(b) == 1:
                return stack[stack.index(b):] + [b]
            if b not in state:
                c = visit(b)
                if c:
                    return c
        stack.pop()
        state[r] = 2
        return None

    for r in sorted(decl):
        if r not in state:
            c = visit(r)
            if c:
                return c
    return None


def closure(decl):
    allowed = {}
    for r in decl:
        seen, todo = set(), list(decl[r])
        while todo:
            b = todo.pop()
            if b not in seen:
                seen.add(b)
                todo.extend(decl.get(b, []))
        allowed[r] = seen
    return allowed


def sources(root):
    for top in TOP:
        for d, dirs, files in os.walk(os.path.join(root, top)):
            dirs[:] = sorted(x for x in dirs if not x.startswith("."))
            for name in sorted(files):
                if name.endswith((".c", ".h")):
                    yield os.path.relpath(os.path.join(d, name), root)


def room_of(rel):
    return os.path.dirname(rel).replace(os.sep, "/")


def room_cycle(arrows):
    """A circle between rooms of the code's graph {room: set(rooms)}, or None."""
    graph = {a: sorted(bs) for a, bs in arrows.items()}
    return declared_cycle(graph)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--root", default=os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    ap.add_argument("--print", action="store_true", help="list the rooms and their arrows")
    args = ap.parse_args()
    root = os.path.realpath(args.root)
    design = os.path.join(root, "docs", "design.md")
    problems = []
    if not os.path.exists(design):
        print(f"check_layers.py: {design}: no such file", file=sys.stderr)
        return 1
    decl, where = read_declaration(design)
    if not decl:
        print("docs/design.md: no ```layers block declaring the order of the rooms", file=sys.stderr)
        return 1
    for room, below in sorted(decl.items()):
        for b in below:
            if b not in decl:
                problems.append(f"docs/design.md:{where[room]}: {room} may include {b}, "
                                f"which is not declared")
    c = declared_cycle(decl)
    if c:
        problems.append(f"docs/design.md:{where[c[0]]}: the declaration has a circle: "
                        + " -> ".join(c))
    allowed = closure(decl)

    files = list(sources(root))
    by_name = {}
    for rel in files:
        by_name.setdefault(os.path.basename(rel), []).append(rel)
    for name, rels in sorted(by_name.items()):
        if len(rels) > 1:
            problems.append(f"{rels[1]}:1: the name {name} is borne by {rels[0]} too: an "
                            f"#include \"{name}\" would not say which")
    for room in sorted({room_of(r) for r in files}):
        if room not in decl:
            problems.append(f"{room}/: a room that docs/design.md's ```layers block does not "
                            f"declare")

    arrows = {}
    for rel in files:
        a = room_of(rel)
        with open(os.path.join(root, rel), encoding="utf-8", errors="replace") as f:
            for i, line in enumerate(f, 1):
                m = INCLUDE.match(line)
                if not m:
                    continue
                hits = by_name.get(os.path.basename(m.group(1)), [])
                if not hits:
                    continue  # a system or dependency header
                b = room_of(hits[0])
                if b == a:
                    continue
                arrows.setdefault(a, {}).setdefault(b, 0)
                arrows[a][b] += 1
                if a in decl and b in decl and b not in allowed[a]:
                    problems.append(f"{rel}:{i}: includes {m.group(1)} ({b}/), which room {a}/ "
                                    f"may not use (docs/design.md \"Rooms\")")
    c = room_cycle({a: set(bs) for a, bs in arrows.items()})
    if c:
        problems.append(f"{c[0]}/: a circle between rooms: " + " -> ".join(c))

    if args.print:
        for a in sorted(arrows):
            print(f"{a}: " + " ".join(f"{b}({n})" for b, n in sorted(arrows[a].items())))
    for p in problems:
        print(p, file=sys.stderr)
    print(f"check_layers.py: {len(files)} files in {len({room_of(r) for r in files})} rooms, "
          f"{sum(len(b) for b in arrows.values())} arrows between rooms, {len(problems)} problem(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
