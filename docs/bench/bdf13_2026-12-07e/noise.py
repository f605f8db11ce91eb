#!/usr/bin/python3
"""noise.py -> noise.txt: the paper's table's noise floor from noise.sh's runs: each run at the
longest step 1/220 s (-9 %) and 1/180 s (+11 %) against the 5 ms one and against each other,
beside the 5 ms run against its half tolerance (max over whole seconds of |(dx, dz)|, mm;
../speed10_2026-12-07c/check.py's measure, through check.py's import)."""
import check

c = check.c10
print(__doc__.strip().replace("\n", "\n# ").join(["# ", ""]))
for base, pre, half in (("o1_2.5e-4_paper", "n1_2.5e-4", "o1_1.25e-4_paper"),
                        ("o2_2.5e-4_paper", "n2_2.5e-4", "o2_1.25e-4_paper"),
                        ("o2_1e-3_paper", "n2_1e-3", "o2_5e-4_paper"),
                        ("lin_1e-3_paper", "nlin_1e-3", "lin_5e-4_paper")):
    print(f"{base}: -9 % {c.err(pre + '_220', base):.3f}, +11 % {c.err(pre + '_180', base):.3f}, "
          f"-9 % vs +11 % {c.err(pre + '_220', pre + '_180'):.3f}; half tolerance "
          f"{c.err(base, half):.3f}")
