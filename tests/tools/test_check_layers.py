#!/usr/bin/env python3
"""test_check_layers.py: tools/check_layers.py fails on the faults it is there to find.

    /usr/bin/python3 tests/tools/test_check_layers.py SOURCE_DIR

Builds tiny fixture trees in a temporary folder (a docs/design.md with a ```layers block and a few
headers under the top folders) and runs the check on each: a tree that keeps the order passes;
a back arrow, a sideways arrow between unordered rooms, a room the declaration does not name, a
circle in the declaration, and a name borne by two files each fail with a line naming the cause.
(tools_layers runs the same check on the real tree.)
"""

import os
import subprocess
import sys
import tempfile

DESIGN = """# design

## Rooms

```layers
core/base:
gaits: core/base
terrains: core/base
contact: terrains
robot: contact gaits
{extra}
```
"""

GOOD = {
    "core/base/core_status.h": "",
    "gaits/gaits_csv.h": '#include "core_status.h"\n',
    "terrains/terrains_terrain.h": '#include "core_status.h"\n#include <ode/ode.h>\n',
    "contact/contact_soft.c": '#include "terrains_terrain.h"\n#include "core_status.h"\n',
    "robot/robot_leg.h": '#include "contact_soft.h"\n#include "gaits_csv.h"\n',
    "contact/contact_soft.h": "",
}


def run(check, files, extra=""):
    with tempfile.TemporaryDirectory() as root:
        os.makedirs(os.path.join(root, "docs"))
        with open(os.path.join(root, "docs", "design.md"), "w", encoding="utf-8") as f:
            f.write(DESIGN.format(extra=extra))
        for rel, text in files.items():
            os.makedirs(os.path.join(root, os.path.dirname(rel)), exist_ok=True)
            with open(os.path.join(root, rel), "w", encoding="utf-8") as f:
                f.write(text)
        p = subprocess.run([sys.executable, check, "--root", root], capture_output=True, text=True)
        return p.returncode, p.stderr + p.stdout


def main():
    check = os.path.join(sys.argv[1], "tools", "check_layers.py")
    cases = [
        ("the fixture that keeps the order", GOOD, "", 0, "0 problem"),
        ("a back arrow (contact/ includes robot/)",
         dict(GOOD, **{"contact/contact_geom.c": '\n#include "robot_leg.h"\n'}), "", 1,
         "contact/contact_geom.c:2: includes robot_leg.h (robot/)"),
        ("a back arrow from the leaf helpers",
         dict(GOOD, **{"core/base/core_h5.c": '#include "gaits_csv.h"\n'}), "", 1,
         "core/base/core_h5.c:1: includes gaits_csv.h"),
        ("a sideways arrow between unordered rooms (gaits/ -> terrains/)",
         dict(GOOD, **{"gaits/gaits_design.c": '#include "terrains_terrain.h"\n'}), "", 1,
         "room gaits/ may not use"),
        ("a room the declaration does not name",
         dict(GOOD, **{"robot/rod/robot_rod.h": '#include "robot_leg.h"\n'}), "", 1,
         "robot/rod/: a room that"),
        ("a circle in the declaration", GOOD, "core/base: robot", 1,
         "the declaration has a circle"),
        ("a name borne by two files",
         dict(GOOD, **{"robot/gaits_csv.h": ""}), "", 1, "is borne by"),
    ]
    failed = 0
    for what, files, extra, want_rc, want_text in cases:
        rc, out = run(check, files, extra)
        ok = rc == want_rc and want_text in out
        failed += not ok
        print(f"{'ok  ' if ok else 'FAIL'} {what}: exit {rc} (want {want_rc})"
              + ("" if ok else f", output:\n{out}"))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
