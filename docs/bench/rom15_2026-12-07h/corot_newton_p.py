#!/usr/bin/python3
"""rom14's corotated scripts with the mixed bulk's pressure space enriched (rom15, issue 34).

    corot_newton_p.py [--penrich E.h5 --pk K] [--psup] [--script newton] <that script's arguments>

--script names the rom14 script run with the enriched Energy: newton (corot_newton.py, the
default), consistency (corot_consistency.py), iterates (corot_iterates.py); --lsup K gives the
latter two corot_newton.py's --sup K (V's last K columns as local modes).

The reduced potential's mixed bulk b^T A^-1 b / 2, b = P^T (v_e - V_e), A = P^T diag(V_e /
kappa) P (rom11_energy.Energy.bulk_mixed) with P replaced by [P, D_K]: the first K dilatation
modes of pressure_enrich.py (E.h5 /D: volume-orthonormal, orthogonal to P). With --psup their
supremizers (E.h5 /Ds) are appended to the basis' V, so corot_newton.py's `--sup K` takes them
as local modes (its --sup uses V's last K columns, M-orthonormalised against the local modes).
Everything else is the rom14 script's (the manifold, the damped Newton / BFGS, the log lines).
"""
import argparse
import os
import runpy
import sys

ROM14 = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "rom14_2026-12-07g")
sys.path.insert(0, ROM14)
import corot  # noqa: E402,F401  (first: it sets the one-thread BLAS before numpy loads)
import corot_newton  # noqa: E402
import h5py  # noqa: E402
import numpy as np  # noqa: E402

_Energy = corot_newton.Energy


def enriched_energy(penrich, pk, psup):
    def make(*args, **kw):
        m = _Energy(*args, **kw)
        if penrich and pk > 0:
            with h5py.File(penrich, "r") as f:
                D = f["D"][:, :pk]
                Ds = f["Ds"][:, :pk] if psup else None
            m.P = np.concatenate([m.P, D], axis=1)
            A = (m.P * (m.Ve / m.kappa)[:, None]).T @ m.P
            m.Ainv_half = np.linalg.inv(np.linalg.cholesky(A))
            if Ds is not None:
                m.V = np.concatenate([m.V, Ds], axis=1)
            print(f"corot_newton_p: pressure space P = {m.P.shape[1] - pk} + {pk} modes of "
                  f"{os.path.basename(penrich)}{' (+ their supremizers in V)' if psup else ''}",
                  flush=True)
        return m
    return make


def main():
    ap = argparse.ArgumentParser(add_help=False)
    ap.add_argument("--penrich", default=None)
    ap.add_argument("--pk", type=int, default=0)
    ap.add_argument("--psup", action="store_true")
    ap.add_argument("--script", choices=("newton", "consistency", "iterates"), default="newton")
    ap.add_argument("--lsup", type=int, default=0,
                    help="consistency / iterates: V's last LSUP columns join the local modes "
                    "(corot_newton.py's --sup, which those scripts lack)")
    a, rest = ap.parse_known_args()
    script = os.path.join(ROM14, f"corot_{a.script}.py")
    sys.argv = [script] + rest
    # the rom14 scripts build their Energy through corot_newton's name (load_manifold, main)
    corot_newton.Energy = enriched_energy(a.penrich, a.pk, a.psup)
    if a.lsup:
        load = corot_newton.load_manifold

        def load_sup(args):
            m, mf = load(args)
            return m, corot_newton.Manifold(m, mf.sl, mf.Vs, m.orth(mf.Vl, m.V[:, -a.lsup:]))
        corot_newton.load_manifold = load_sup
    if a.script == "newton":
        corot_newton.main()
    else:
        runpy.run_path(script, run_name="__main__")


if __name__ == "__main__":
    main()
