#!/usr/bin/env python3
"""test_cli_help.py: one command line for every crawlsim command (issue 36).

Proves: `crawlsim --version` exits 0 naming the build and ODE, SUNDIALS, HDF5, MUMPS;
`--help` of every command and subcommand exits 0; every option a command's parser compares in
its source (a "--name" literal in tools/cmd_*.c) is listed in that file's commands' help, and
every listed option is accepted by the parser (not "unknown option"); every value option takes
--name=VALUE (an empty one is "needs a value", not unknown) and every flag refuses
--flag=VALUE; an option with one letter dropped is refused, exit 1, naming the option in
"did you mean"; one error line each; the study file's option lists (tools/study_file.c) name
only options of their commands. Prints "N passed, N failed"; exit 1 on any failure.
Usage: /usr/bin/python3 test_cli_help.py PATH_TO_CRAWLSIM SOURCE_DIR
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

passed = failed = 0
TMP = tempfile.mkdtemp(prefix="cli_help_")


def check(cond, what):
    global passed, failed
    if cond:
        passed += 1
    else:
        failed += 1
        print(f"FAIL {what}")


def run(exe, args):
    env = dict(os.environ, OMP_WAIT_POLICY="PASSIVE")  # no re-exec (crawlsim.c passiveWaits)
    p = subprocess.run([exe] + args, env=env, capture_output=True, text=True, timeout=120,
                       stdin=subprocess.DEVNULL, cwd=TMP)
    return p.returncode, p.stdout, p.stderr


# command -> the source file whose option table and parser it uses
COMMANDS = {
    "run": "cmd_run.c", "bend": "cmd_bend.c", "gait check": "cmd_gait.c",
    "gait design": "cmd_gaitdesign.c", "gait flat-road": "cmd_gaitdesign.c",
    "calibrate": "cmd_calibrate.c", "study": "cmd_study.c", "export": "cmd_export.c",
    "rom snapshots": "cmd_rom_snapshots.c", "rom check": "cmd_rom_check.c",
    "rom ecsw-matrix": "cmd_rom_ecsw.c",
}


def main():
    exe, src = sys.argv[1], sys.argv[2]
    rc, out, err = run(exe, ["--version"])
    check(rc == 0 and out.startswith("crawlsim ") and all(
        w in out for w in ("ODE", "SUNDIALS", "HDF5", "MUMPS")), f"--version: {rc} {out!r}")
    for args in (["--help"], ["gait", "--help"], ["rom", "--help"]):
        rc, out, _ = run(exe, args)
        check(rc == 0 and "usage" in out, f"{' '.join(args)} exits 0 with a usage")
    listed_by_file = {}
    for cmd, f in COMMANDS.items():
        rc, out, err = run(exe, cmd.split() + ["--help"])
        check(rc == 0 and out.startswith("usage: crawlsim " + cmd), f"{cmd} --help exits 0")
        opts = re.findall(r"^  (--[a-z0-9-]+)(?: (\S+))?$", out, re.M)
        check(len(opts) > 1, f"{cmd} --help lists options")
        check(out.count("[default:") >= 1, f"{cmd} --help states defaults")
        listed_by_file.setdefault(f, set()).update(o for o, _ in opts)
        for o, arg in opts:
            if o == "--help":
                continue
            # accepted by the parser (an unknown option after it stops the command before any
            # work: every parser reads all its arguments first)
            rc, _, e = run(exe, cmd.split() + ([o, "1"] if arg else [o]) + ["--zz-unknown"])
            check(rc == 1 and f"unknown option {o}" not in e and e.count("\n") == 1,
                  f"{cmd} {o} accepted: {e!r}")
            # --name=VALUE: an empty value is a missing value; a flag refuses a value
            rc, _, e = run(exe, cmd.split() + [o + "="])
            if arg:
                check(rc == 1 and "needs a value" in e and e.count("\n") == 1,
                      f"{cmd} {o}= is a missing value: {e!r}")
            else:
                check(rc == 1 and "takes no value" in e, f"{cmd} {o}= refused: {e!r}")
            # a typo names the option
            typo = o[:3] + o[4:] if len(o) > 5 else o + "x"
            rc, _, e = run(exe, cmd.split() + [typo, "1"])
            check(rc == 1 and f"did you mean {o}?" in e and e.count("\n") == 1,
                  f"{cmd} {typo} suggests {o}: {e!r}")
    # every option literal a parser compares is listed by its file's commands
    for f, listed in listed_by_file.items():
        text = open(os.path.join(src, "tools", f), encoding="utf-8").read()
        used = set(re.findall(r'strcmp\(\w+, "(--[a-z0-9-]+)"\)', text))
        used |= set(re.findall(r'csx_optIs\([^,]+, "(--[a-z0-9-]+)"\)', text))
        used.discard("--help")
        check(used and used <= listed, f"{f}: parsed but not in --help: {sorted(used - listed)}")
    # the study file's own option lists (tools/study_file.c) name only options its commands
    # take (a study case runs the command's parser in-process)
    text = open(os.path.join(src, "tools", "study_file.c"), encoding="utf-8").read()
    for table, cmd in (("kBendOpts", "bend"), ("kRunOpts", "run"),
                       ("kCalibrateOpts", "calibrate"), ("kGaitDesignOpts", "gait design")):
        body = re.search(r"static const OptSpec " + table + r"\[\] = \{(.*?)\};", text, re.S)
        names = set(re.findall(r'"(--[a-z0-9-]+)"', body.group(1) if body else "")) - {"--help"}
        rc, out, _ = run(exe, cmd.split() + ["--help"])
        listed = set(re.findall(r"^  (--[a-z0-9-]+)", out, re.M))
        check(names and names <= listed,
              f"study_file.c {table}: not options of {cmd}: {sorted(names - listed)}")
    rc, _, e = run(exe, ["run", "--t-edn", "3"])
    check(rc == 1 and e == "crawlsim run: unknown option --t-edn; did you mean --t-end? "
          "(see crawlsim run --help)\n", f"run --t-edn: {e!r}")
    rc, _, e = run(exe, ["frobnicate"])
    check(rc == 1 and e.count("\n") == 1, "unknown command: one line, exit 1")
    shutil.rmtree(TMP, ignore_errors=True)
    print(f"{passed} passed, {failed} failed")
    return 0 if failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
