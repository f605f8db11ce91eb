#!/usr/bin/python3
"""romfib_fibre_span.py: what fibre strain bases hold (branch romfib, docs/notes/rom.md).

    /usr/bin/python3 docs/bench/rom/romfib_fibre_span.py SNAPDIR LEG.h5 BASIS.h5 ...

For each basis file's Qf [nfib, mf]: the W-weighted (W = EA L0) relative projection error
|E - Q Q^T W E|_W / |E|_W of the training FE states' fibre Green strains E and stresses S(E)
(the largest over the states), and of each held-out ray's strains state by state (t = 0.25,
0.5, 0.75, 1). LEG.h5 lends the fibre elements (as rom_basis.py --fibres). Dimensionless.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..",
                                "tools"))
import h5py  # noqa: E402
import numpy as np  # noqa: E402
import rom_basis as rb  # noqa: E402


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__.split("\n\n")[1].strip())
    snap, leg, bases = sys.argv[1], sys.argv[2], sys.argv[3:]
    x, _, fixed, _, _ = rb.read_mesh(snap)
    fib = rb.read_fibres(leg, x)
    W = fib[3] * fib[2]
    rays = rb.read_rays(snap)

    def strains(r):
        U = r["u"].T.copy()
        U[fixed] = 0.0
        return rb.fibre_strains(U, x, fib)

    train = [r for r in rays if r["kind"] == "train"]
    E = np.concatenate([strains(r) for r in train], axis=1)
    S = rb.fibre_law(E, fib[4])
    held = [(r["name"], r["t"], strains(r)) for r in rays if r["kind"] == "test"]
    print(f"romfib_fibre_span: {len(train)} training rays ({E.shape[1]} FE states), "
          f"{len(held)} held-out rays, {E.shape[0]} fibres")

    for path in bases:
        with h5py.File(path, "r") as f:
            Q = f["Qf"][...]

        def perr(T):
            R = T - Q @ (Q.T @ (W[:, None] * T))
            return (np.sqrt(np.einsum("fj,fj,f->j", R, R, W)) /
                    np.maximum(np.sqrt(np.einsum("fj,fj,f->j", T, T, W)), 1e-300))

        print(f"{os.path.basename(path)}: mf = {Q.shape[1]}: training strains max "
              f"{perr(E).max():.3f}, stresses max {perr(S).max():.3f}")
        for name, t, Et in held:
            e = perr(Et)
            print(f"  {name:8s} " + "  ".join(f"t {tt:.2f}: {ee:.3f}" for tt, ee in zip(t, e)))


if __name__ == "__main__":
    main()
