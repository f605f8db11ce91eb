#!/usr/bin/env python3
"""stages.py CG [CG...]: ../strainspeed_2026-12-06f/stages.py (instructions per simulated second
by stage from callgrind files of bench_strain_driver) with one row more under the calibration:
its RBF field alone (csr_rodActuationEval_), the part the lattice (cal_quantum) saves."""
import os

orig = os.path.join(os.path.dirname(os.path.abspath(__file__)), "../strainspeed_2026-12-06f/stages.py")
row = '    ("legs: calibration (csr_strainActuate)", ["csr_strainActuate"]),\n'
src = open(orig).read()
assert row in src
src = src.replace(row, row + '    ("  of which the RBF field (csr_rodActuationEval_)", ["csr_rodActuationEval_"]),\n')
exec(compile(src, orig, "exec"))
