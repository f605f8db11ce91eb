#!/usr/bin/python3
"""romecsw_subset_training.py: a copy of a basis file (tools/rom_basis.py) whose training states
(q_snap, p_snap, g_snap, F_snap: what `crawlsim rom ecsw-matrix` fits on) are those of the named
rays only, every K-th of them; every other dataset and attribute bit for bit (docs/notes/rom.md,
"ECSW on the real leg's fibre basis").

Why: a basis whose displacement span V is the POD of some rays (rom_basis.py --v-rays) lists the
states of every training ray, and the states of the rays outside V project onto it badly (on the
real leg's 13 rays' V a full-load state of another ray inverts an element at its projection, and
ecsw-matrix stops there). The fit belongs on the states V was made to hold.

The states are listed as rom_basis.py writes them: the training rays in the file's train_rays
order, each ray's states in turn, then the same list once per quarter turn (attribute turns).

    /usr/bin/python3 romecsw_subset_training.py BASIS.h5 OUT.h5 [--rays A,B,...] [--every K]

--rays defaults to the file's v_rays (every training ray when it has none); --every 1.
"""
import argparse
import os
import sys

import h5py
import numpy as np


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("basis")
    ap.add_argument("out")
    ap.add_argument("--rays", default=None)
    ap.add_argument("--every", type=int, default=1)
    a = ap.parse_args()
    if a.every < 1:
        sys.exit(f"romecsw_subset_training: --every {a.every}: not a whole number >= 1")
    with h5py.File(a.basis, "r") as f:
        train = str(f.attrs["train_rays"]).split(",")
        want = (a.rays or str(f.attrs.get("v_rays", "")) or ",".join(train)).split(",")
        bad = [r for r in want if r not in train]
        if bad:
            sys.exit(f"romecsw_subset_training: {a.basis}: {bad[0]} is not a training ray "
                     f"(train_rays {','.join(train)})")
        ns = f["q_snap"].shape[0]
        ns_fe = int(f.attrs["nsnap_fe"])
        per = ns_fe // len(train)
        if per * len(train) != ns_fe or ns % ns_fe:
            sys.exit(f"romecsw_subset_training: {a.basis}: {ns_fe} FE states are not "
                     f"{len(train)} rays of equal length, or {ns} not whole turns of them")
        cols = [k * ns_fe + train.index(r) * per + s
                for k in range(ns // ns_fe) for r in train if r in want for s in range(per)]
        cols = np.array(cols[::a.every])
        with h5py.File(a.out + ".tmp", "w") as o:
            for key, v in f.attrs.items():
                o.attrs[key] = v
            o.attrs["subset_of"] = os.path.abspath(a.basis)
            o.attrs["subset_rays"] = ",".join(r for r in train if r in want)
            o.attrs["subset_every"] = a.every
            o.attrs["nsnap"] = len(cols)
            for key in f:
                if key in ("q_snap", "p_snap", "g_snap", "F_snap"):
                    o[key] = f[key][...][cols]
                else:
                    f.copy(key, o)
    os.replace(a.out + ".tmp", a.out)
    print(f"romecsw_subset_training: {len(cols)} of {ns} training states ({len(want)} rays, "
          f"every {a.every}) -> {a.out}")


if __name__ == "__main__":
    main()
