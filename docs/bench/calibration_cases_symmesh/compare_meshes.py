#!/usr/bin/python3
"""Each finished case on the symmetric mesh against the same case of the whole-body full table:
the largest tip distance over the shared pressure rows, and at the last shared row, plus the
bend of every segment there (deg). Run from the repository root:

    /usr/bin/python3 docs/bench/calibration_cases_symmesh/compare_meshes.py CASES_DIR
"""
import glob
import os
import sys

import h5py
import numpy as np

cases = sys.argv[1] if len(sys.argv) > 1 else 'docs/bench/calibration_cases_symmesh/cases'
full = h5py.File('robot/calibration_fe_leg_modes_full.h5', 'r')
print('%-18s %8s %10s %10s  %s' % ('case', 'p_last', 'max |dtip|', 'last |dtip|',
                                   'bend (deg) symmetric / whole-body, per segment'))
for path in sorted(glob.glob(os.path.join(cases, '*.h5'))):
    name = os.path.basename(path)[:-3]
    g = h5py.File(path, 'r')['cases/' + name]
    if name not in full['cases']:
        print('%-18s not in the whole-body table' % name)
        continue
    o = full['cases/' + name]
    pn, po = np.array(g['pressure']), np.array(o['pressure'])
    # the rows both have (a sweep under volume control may step over a row)
    rows = [(i, j) for i, p in enumerate(pn) for j, q in enumerate(po) if abs(p - q) < 1e-9]
    if not rows:
        print('%-18s no shared pressure rows' % name)
        continue
    i, j = np.array(rows).T
    d = np.linalg.norm(np.array(g['tip'])[i] - np.array(o['tip'])[j], axis=1)
    bn = np.degrees(np.linalg.norm(np.array(g['bend'])[i[-1]], axis=1))
    bo = np.degrees(np.linalg.norm(np.array(o['bend'])[j[-1]], axis=1))
    print('%-18s %8.3f %10.2f %10.2f  %s / %s' % (name, pn[i[-1]], d.max(), d[-1],
                                                  np.round(bn, 2), np.round(bo, 2)))
