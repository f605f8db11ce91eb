"""The package's ctypes mirror of core/crawlsim.h (crawlsim/_lib.py) against the installed
header: a C program compiled against PREFIX/include prints every mirrored struct's size and
every field's offset, which must equal ctypes'. A field added to, removed from or moved in the
header without the mirror fails here, before it can corrupt a call."""

import ctypes
import os
import re
import shutil
import subprocess

import pytest

from crawlsim import _lib

STRUCTS = {"csRunDef": _lib.csRunDef, "csRunResult": _lib.csRunResult,
           "csBendDef": _lib.csBendDef, "csError": _lib.csError}


def c_layout(tmp_path):
    prefix = os.environ["CRAWLSIM_TEST_PREFIX"]
    cc = shutil.which("cc") or shutil.which("gcc")
    if cc is None:
        pytest.fail("no C compiler (cc) to check the layout with")
    lines = ["#include <stddef.h>", "#include <stdio.h>", "#include <crawlsim/crawlsim.h>",
             "int main(void) {"]
    for name, st in STRUCTS.items():
        lines.append(f'  printf("{name} %zu\\n", sizeof({name}));')
        for field, _ in st._fields_:
            lines.append(f'  printf("{name}.{field} %zu\\n", offsetof({name}, {field}));')
    lines += ["  return 0;", "}"]
    src = tmp_path / "layout.c"
    src.write_text("\n".join(lines) + "\n")
    exe = tmp_path / "layout"
    r = subprocess.run([cc, "-std=c17", "-I", os.path.join(prefix, "include"), str(src), "-o",
                        str(exe)], capture_output=True, text=True)
    assert r.returncode == 0, "the mirror names a field the header lacks:\n" + r.stderr
    out = subprocess.run([str(exe)], capture_output=True, text=True, check=True).stdout
    return dict(line.rsplit(" ", 1) for line in out.splitlines())


def test_ctypes_mirror_matches_the_installed_header(tmp_path):
    c = c_layout(tmp_path)
    bad = []
    for name, st in STRUCTS.items():
        if int(c[name]) != ctypes.sizeof(st):
            bad.append(f"sizeof({name}): C {c[name]}, ctypes {ctypes.sizeof(st)}")
        for field, _ in st._fields_:
            off = getattr(st, field).offset
            if int(c[f"{name}.{field}"]) != off:
                bad.append(f"{name}.{field}: C offset {c[name + '.' + field]}, ctypes {off}")
    assert not bad, "\n".join(bad)


def test_every_function_of_the_header_is_bound():
    """Every CS_API function the installed header declares has a prototype in _lib (so none
    is called with ctypes' default int arguments)."""
    prefix = os.environ["CRAWLSIM_TEST_PREFIX"]
    text = open(os.path.join(prefix, "include", "crawlsim", "crawlsim.h")).read()
    declared = set(re.findall(r"CS_API\b[^;(]*?\b(cs_\w+)\s*\(", text))
    missing = declared - set(_lib.PROTOTYPES)
    assert not missing, f"functions of crawlsim.h without a ctypes prototype: {sorted(missing)}"
