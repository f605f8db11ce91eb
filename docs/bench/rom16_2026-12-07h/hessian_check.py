#!/usr/bin/python3
"""The septa's Hessian of septa_relax.py checked at T_R's representation (rom16).

    hessian_check.py SNAP BASIS.h5 LEG.h5 ROD.h5 LOCAL.h5

The local model's forces against the full model's on the septa's dofs (must agree exactly), the
coloured forward-difference Hessian's asymmetry, H v against a directional difference of the force
along a random v, its smallest eigenvalues (shift-invert) and the Newton step's slope g . dx.
"""
import os
import sys
import warnings

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from septa_relax import *  # noqa: E402,F401,F403
from scipy.sparse.linalg import eigsh  # noqa: E402

warnings.filterwarnings("ignore")
a = manifold_args([]).parse_args()
m, mf = load_manifold(a); m.Qf = None
sel, fnode = septa_select(m)
s = local_model(m, fnode)
fi, col, A = colouring(m, fnode)
(name, tt, u, p, _, _), = list(states(a.snap, ["T_R"], [1.0], m.fixed))
w = mf.u(represent_z(m, mf, u))
dofs = (3 * fi[:, None] + np.arange(3)).ravel(); dofs = dofs[~m.fixed[dofs]]
# check local model's forces vs full on dofs
f1 = m.total(w, p, fe=True)[1][dofs]; f2 = s.total(w, p, fe=True)[1][dofs]
print("local vs full force", np.abs(f1-f2).max(), np.abs(f1).max())
# build H via relax internals: copy code
h=1e-6
pos = -np.ones(3 * m.nn, np.int64); pos[dofs] = np.arange(dofs.size)
f = s.total(w, p, fe=True)[1]
Af = A[fi].tocoo(); rr, cc, vv = [], [], []
for c in range(col.max()+1):
    nodes_c = fi[col == c]; msk = col[Af.row] == c; ki, kk = Af.row[msk], Af.col[msk]
    for d in range(3):
        e = np.zeros(3 * m.nn); e[3 * nodes_c + d] = h; e[m.fixed] = 0.0
        df = (s.total(w + e, p, fe=True)[1] - f) / h
        jcol = pos[3 * fi[ki] + d]
        for dd in range(3):
            irow = pos[3 * kk + dd]; ok = (irow >= 0) & (jcol >= 0)
            rr.append(irow[ok]); cc.append(jcol[ok]); vv.append(df[3 * kk[ok] + dd])
H = sp.coo_matrix((np.concatenate(vv), (np.concatenate(rr), np.concatenate(cc))), shape=(dofs.size, dofs.size)).tocsr()
print("asym", abs(H-H.T).max(), abs(H).max())
rng = np.random.default_rng(0); v = rng.standard_normal(dofs.size)
e = np.zeros(3*m.nn); e[dofs] = 1e-6*v
hv = (s.total(w+e,p,fe=True)[1][dofs] - f[dofs])/1e-6
print("Hv check", np.linalg.norm(H@v - hv)/np.linalg.norm(hv))
Hs = 0.5*(H+H.T)
print("smallest eig", eigsh(Hs.tocsc(), k=3, sigma=-1e3, which='LM', return_eigenvectors=False))
g = f[dofs]; dx = -spsolve(Hs.tocsc(), g); print("g.dx", g@dx, "|dx|max", np.abs(dx).max())
