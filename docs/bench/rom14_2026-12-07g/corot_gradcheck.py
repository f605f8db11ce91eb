#!/usr/bin/python3
"""Verification of corot_newton.py's reduced gradient J(z)^T f(u(z)) against central
differences of the reduced potential Pi(u(z)) along random directions and along single
strain and local coordinates, at the held-out state's representation (rom14).
    corot_gradcheck.py SNAP BASIS.h5 LEG.h5 ROD.h5 LOCAL.h5 [--r 12 --k 176 --ray T_R --t 1]"""
import os
import sys
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import numpy as np  # noqa: E402
import corot_newton as cn  # noqa: E402

sys.argv += ["--newton", "0"]
state = {}
orig = cn.Manifold.grad


def grad(self, z, p):
    state["mf"], state["z"], state["p"] = self, z.copy(), p
    return orig(self, z, p)


cn.Manifold.grad = grad
cn.main()
mf, z, p = state["mf"], state["z"], state["p"]
_, g, gp, _, J, f = orig(mf, z, p)
rng = np.random.default_rng(1)
dirs = [("random", rng.standard_normal(mf.n)) for _ in range(2)]
for j in (0, 5, mf.r, mf.r + 50):
    e = np.zeros(mf.n)
    e[j] = 1.0
    dirs.append((f"coordinate {j}", e))
for lab, d in dirs:
    d = d / np.linalg.norm(d)
    for h in (1e-4, 1e-5):
        ep = sum(mf.m.total(mf.u(z + h * d), p)[0])
        em = sum(mf.m.total(mf.u(z - h * d), p)[0])
        fd = (ep - em) / (2 * h)
        print(f"corot_gradcheck: {lab:14s} h {h:g}: g.d {g @ d:+.6e}, differences {fd:+.6e}, "
              f"relative gap {abs(fd - g @ d) / max(abs(fd), 1e-30):.2e} (|g| {np.linalg.norm(g):.3g})", flush=True)
# the Hessian (corot_newton.py's) against differences of the reduced gradient along d
H = mf.hessian(z, p, J, f)
for lab, d in dirs[:3]:
    d = d / np.linalg.norm(d)
    for h in (1e-5, 1e-6):
        gpl = orig(mf, z + h * d, p)[1]
        gmi = orig(mf, z - h * d, p)[1]
        fd = (gpl - gmi) / (2 * h)
        print(f"corot_gradcheck: Hessian along {lab:14s} h {h:g}: |H d - differences| / |H d| "
              f"{np.linalg.norm(H @ d - fd) / np.linalg.norm(H @ d):.2e}", flush=True)
