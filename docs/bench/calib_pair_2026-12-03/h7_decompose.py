#!/usr/bin/python3
"""H7 (or any case) per segment and row: the model's bend magnitude, direction and stretch against
the FE, and the tip error with the FE's value substituted for one quantity at a time.
Usage (from the repository root): /usr/bin/python3 docs/bench/calib_pair_2026-12-03/h7_decompose.py
[CASE [RULE]] (RULE a tools/calib_rules.py rule: rbf, sup, rbf-pair)."""
import sys, math, numpy as np
sys.path.insert(0, 'tools')
import calib_rules as cr
cases, leg = cr.load(['robot/calibration_fe_leg_modes.h5','docs/bench/calibration_cases_2026-12-02b/H8.h5'])
name = sys.argv[1] if len(sys.argv)>1 else 'H7'
rule = sys.argv[2] if len(sys.argv)>2 else 'rbf'
M = cr.MODELS.get(rule, cr.Model)(cases, leg, cr.RULES[rule])
c = cases[name]
DEG = cr.DEG
print(name, 'ratio', c.ratio, 'rule', rule)
for i in range(len(c.p)):
    p = c.p[i]
    if p < 0.2 - 1e-9 and p not in (0.1,): continue
    bm, sm = [], []
    for s in range(3):
        b, st = M.eval(s, c.ratio*p); bm.append(b); sm.append(st)
    bf = [c.bend[i,s] for s in range(3)]; sf = [c.stretch[i,s] for s in range(3)]
    tm = cr.tip_of(leg, bm, sm); tcc = cr.tip_of(leg, bf, sf); tfe = c.tip[i]
    print('p %.3f  tip err %.2f mm (model-FE) ; cc kinematics of FE segs vs FE tip %.2f mm; model tip vs FE-cc tip %.2f' % (p, np.linalg.norm(tm-tfe), np.linalg.norm(tcc-tfe), np.linalg.norm(tm-tcc)))
    for s in range(3):
        mb, fb = np.linalg.norm(bm[s]), np.linalg.norm(bf[s])
        da = (math.degrees(math.atan2(bm[s][1], bm[s][0]) - math.atan2(bf[s][1], bf[s][0])) + 180) % 360 - 180
        print('   seg%d |bend| model %7.2f FE %7.2f (d %+6.2f deg) dir d %+6.2f deg ; stretch model %.4f FE %.4f (d %+.4f = %+.2f mm of S)' % (
            s+1, mb/DEG, fb/DEG, (mb-fb)/DEG, da, sm[s], sf[s], sm[s]-sf[s], (sm[s]-sf[s])*leg['S'][s]))
    # substitutions
    def sub(what, segs=(0,1,2)):
        b2 = [x.copy() for x in bm]; s2 = list(sm)
        for s in segs:
            mb, fb = np.linalg.norm(bm[s]), np.linalg.norm(bf[s])
            if 'mag' in what: b2[s] = b2[s]/np.linalg.norm(b2[s])*fb
            if 'dir' in what: b2[s] = bf[s]/fb*np.linalg.norm(b2[s])
            if 'st' in what: s2[s] = sf[s]
        return np.linalg.norm(cr.tip_of(leg, b2, s2) - tfe)
    print('   tip err with FE value substituted: mag %.2f  dir %.2f  stretch %.2f  mag+dir %.2f  mag+stretch %.2f  dir+stretch %.2f  all %.2f' % (
        sub('mag'), sub('dir'), sub('st'), sub('magdir'), sub('magst'), sub('dirst'), sub('magdirst')))
    print('   stretch subst per seg: ' + ' '.join('%d:%.2f' % (s+1, sub('st', (s,))) for s in range(3)) + '   mag per seg: ' + ' '.join('%d:%.2f' % (s+1, sub('mag', (s,))) for s in range(3)))
