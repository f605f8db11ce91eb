#!/usr/bin/python3
"""steps.py RUN.h5...: each run's status, end time, x(end), steps (macro steps with the 0.3 s
settling), the stages' rejections and the adaptive step's counts and lengths (run-file
attributes), and the CPU seconds of its log (logs/TAG.log beside this script)."""
import os, re, sys
import h5py

here = os.path.dirname(os.path.abspath(__file__))
for path in sys.argv[1:]:
    with h5py.File(path, "r") as f:
        a = f.attrs
        t = f["/time"][:]
        p = f["/support/position"][:]
        st = a.get("status", b"?")
        st = st.decode() if isinstance(st, bytes) else st
        g = lambda k: float(a[k]) if k in a else float("nan")
        tag = os.path.basename(path)[:-3]
        cpu = float("nan")
        log = os.path.join(here, "logs", tag + ".log")
        if os.path.exists(log):
            m = re.search(r"([0-9.]+) user ([0-9.]+) sys", open(log).read())
            if m:
                cpu = float(m.group(1)) + float(m.group(2))
        print(f"{tag:22s} {st:4s} t {t[-1]:6.3f} x {p[-1,0]:7.2f} h {p[-1,1]:6.2f} "
              f"steps {g('steps'):6.0f} stage-rej {g('rejected_steps'):4.0f} "
              f"ada {g('adaptive_steps'):6.0f} rej {g('adaptive_rejected_steps'):4.0f} "
              f"h min/med/max {g('adaptive_h_min_s')*1e3:.3f}/{g('adaptive_h_median_s')*1e3:.3f}/"
              f"{g('adaptive_h_max_s')*1e3:.3f} ms  sub {g('strain_sub_intervals'):.0f}  "
              f"CPU {cpu:.1f} s")
