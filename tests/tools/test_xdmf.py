#!/usr/bin/env python3
"""test_xdmf.py: the .xdmf that `crawlsim run` writes beside its HDF5 file opens in ParaView.

Proves, headless (Debian's ParaView is not installed by tools/install-deps.sh: 5.11 pulls in
~1 GB; when `pvpython` is on PATH it is used as well): a 0.3 s flat-road run writes RUN.xdmf
next to RUN.h5; the XML parses; it has the static terrain grid and a temporal collection
whose frames' times increase and lie within the run's /time; every HDF5 DataItem names a
dataset of the run file (by base name, resolved next to the .xdmf) with exactly the
dimensions it declares; every hyperslab's start/stride/count lies inside its dataset and
yields the shape its item declares; topologies agree with their data (Hexahedron: 8 corners
per element; Polyline: NodesPerElement = the centreline's points); and the data read through
the first and the last frame's hyperslabs is the support box and the legs' centrelines (the
support's corners average to its centre, a leg starts at its hip 65 mm beside the centre
line); every frame carries the attributes contact_force_N (support), pressure_MPa,
foot_force_N and stance (legs); with pvpython, ParaView's XDMF Reader reads every frame and
each block's points and cell data are exactly the run file's series at that frame's sample;
tools/animate_run.py turns the same run into a GIF (Pillow reads its frames). Prints
"N passed, N failed"; exit 1 on any failure.
Usage: /usr/bin/python3 test_xdmf.py PATH_TO_CRAWLSIM
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

import h5py
import numpy as np

passed = failed = 0


def check(cond, what):
    global passed, failed
    if cond:
        passed += 1
        print(f"ok   {what}")
    else:
        failed += 1
        print(f"FAIL {what}")


def dims_of(item):
    return tuple(int(x) for x in item.get("Dimensions").split())


def read_item(item, base):
    """The array a DataItem stands for (HDF, XML or HyperSlab), checking it on the way."""
    kind = item.get("ItemType", "Uniform")
    if kind == "HyperSlab":
        sel, src = list(item)
        s = np.array(sel.text.split(), dtype=int).reshape(3, -1)
        data = read_item(src, base)
        start, stride, count = s
        ok = all(start[i] + (count[i] - 1) * stride[i] < data.shape[i] for i in range(data.ndim))
        if not ok:
            raise ValueError(f"hyperslab {s.tolist()} outside {data.shape}")
        slab = data[tuple(slice(start[i], start[i] + count[i] * stride[i], stride[i])
                          for i in range(data.ndim))]
        slab = slab.reshape(dims_of(item))
        return slab
    if item.get("Format") == "HDF":
        fname, path = item.text.strip().split(":", 1)
        with h5py.File(os.path.join(base, fname), "r") as f:
            if path not in f:
                raise ValueError(f"{fname} has no {path}")
            arr = f[path][...]
        if arr.shape != dims_of(item):
            raise ValueError(f"{path}: declared {dims_of(item)}, the file has {arr.shape}")
        return arr
    return np.array(item.text.split(), dtype=float).reshape(dims_of(item))


def main():
    if len(sys.argv) < 2:
        print("usage: test_xdmf.py PATH_TO_CRAWLSIM", file=sys.stderr)
        return 2
    exe = sys.argv[1]
    tmp = tempfile.mkdtemp(prefix="cs_test_xdmf.")
    try:
        h5 = os.path.join(tmp, "run.h5")
        r = subprocess.run([exe, "run", "--t-end", "0.3", "--quiet", "--out", h5],
                           capture_output=True, text=True)
        check(r.returncode == 0, f"crawlsim run exits 0 ({r.stderr.strip()[:200]})")
        xdmf = os.path.join(tmp, "run.xdmf")
        check(os.path.isfile(xdmf), "run.xdmf is written beside run.h5")
        if not os.path.isfile(xdmf):
            return 1
        root = ET.parse(xdmf).getroot()
        check(root.tag == "Xdmf" and root.get("Version") == "3.0", "XDMF 3 root")
        dom = root.find("Domain")
        grids = dom.findall("Grid")
        names = [g.get("Name") for g in grids]
        check(names == ["terrain", "robot"], f"top-level grids {names}")
        with h5py.File(h5, "r") as f:
            t = f["/time"][:]
            cl = f["/legs/A/centerline"]
            K = cl.shape[1]
        # every DataItem reads, with its declared shape
        bad = []
        for item in root.iter("DataItem"):
            parent_is_slab = False
            for p in root.iter("DataItem"):
                if p.get("ItemType") == "HyperSlab" and item in list(p):
                    parent_is_slab = True
            if parent_is_slab:
                continue
            try:
                read_item(item, tmp)
            except Exception as e:  # noqa: BLE001 - any failure is a test failure
                bad.append(str(e))
        check(not bad, f"every DataItem reads with its declared shape {bad[:2]}")
        # topologies agree with their geometry
        terr = grids[0]
        hexes = int(terr.find("Topology").get("NumberOfElements"))
        g = read_item(terr.find("Geometry/DataItem"), tmp)
        check(g.shape == (8 * hexes, 3) and hexes >= 1, f"terrain: {hexes} hexahedra, {g.shape}")
        frames = grids[1].findall("Grid")
        times = [float(fr.find("Time").get("Value")) for fr in frames]
        check(grids[1].get("CollectionType") == "Temporal" and len(frames) >= 2,
              f"temporal collection of {len(frames)} frames")
        check(all(b > a for a, b in zip(times, times[1:])) and times[0] >= t[0] - 1e-12
              and times[-1] <= t[-1] + 1e-12, "frame times increase within /time")
        ok_topo = True
        for fr in (frames[0], frames[-1]):
            sub = {s.get("Name"): s for s in fr.findall("Grid")}
            ok_topo &= sorted(sub) == ["leg_" + k for k in "ABCDEFGH"] + ["support"]
            sup = read_item(sub["support"].find("Geometry/DataItem"), tmp)
            ok_topo &= sup.shape == (8, 3)
            centre = sup.mean(axis=0)
            for k in "ABCDEFGH":
                topo = sub["leg_" + k].find("Topology")
                ok_topo &= topo.get("TopologyType") == "Polyline" and \
                    int(topo.get("NodesPerElement")) == K
                conn = read_item(topo.find("DataItem"), tmp)
                ok_topo &= conn.size == K
                leg = read_item(sub["leg_" + k].find("Geometry/DataItem"), tmp)
                ok_topo &= leg.shape == (K, 3)
                # the hip: 65 mm beside the support's centre line (l_AE / 2), under it
                ok_topo &= abs(abs(leg[0, 2] - centre[2]) - 65.0) < 1.0 and leg[0, 1] < centre[1]
        check(ok_topo, "frames hold the support box and 8 centrelines from their hips")
        # the animation of the same run: a GIF whose frames Pillow reads
        gif = os.path.join(tmp, "run.gif")
        here = os.path.dirname(os.path.abspath(__file__))
        anim = os.path.join(here, "..", "..", "tools", "animate_run.py")
        a = subprocess.run([sys.executable, anim, h5, "-o", gif, "--fps", "10", "--speed", "0.5"],
                           capture_output=True, text=True, env=dict(os.environ, MPLBACKEND="Agg",
                                                                    MPLCONFIGDIR=tmp))
        nframes = 0
        if a.returncode == 0 and os.path.isfile(gif):
            from PIL import Image
            with Image.open(gif) as im:
                nframes = getattr(im, "n_frames", 1)
        # 0.3 s at 0.5 simulated s per video s and 10 fps: 6 frames (+1 for t = 0)
        check(a.returncode == 0 and nframes >= 6, f"animate_run.py writes a GIF of {nframes} "
              f"frames {a.stderr.strip()[:200]}")
        # every frame's attributes: the support's contact force, each leg's 12 pressures, its
        # foot force and stance (their DataItems were read above)
        ok_attr = True
        for fr in frames:
            sub = {s.get("Name"): s for s in fr.findall("Grid")}
            ok_attr &= [a.get("Name") for a in sub["support"].findall("Attribute")] == \
                ["contact_force_N"]
            for k in "ABCDEFGH":
                ok_attr &= [a.get("Name") for a in sub["leg_" + k].findall("Attribute")] == \
                    ["pressure_MPa", "foot_force_N", "stance"]
        check(ok_attr, "every frame has contact_force_N, pressure_MPa, foot_force_N, stance")
        pv = shutil.which("pvpython")
        if pv:
            # ParaView's own reader (its "XDMF Reader"), at every frame: the blocks' points and
            # cell data equal the run file's series at that frame's sample
            script = os.path.join(tmp, "pv.py")
            with open(script, "w") as fh:
                fh.write("import json, sys\n"
                         "from paraview.simple import XDMFReader\n"
                         "from paraview import servermanager as sm\n"
                         "r = XDMFReader(FileNames=[sys.argv[1]])\n"
                         "out = []\n"
                         "for t in r.TimestepValues:\n"
                         "    r.UpdatePipeline(t)\n"
                         "    it = sm.Fetch(r).NewIterator(); it.InitTraversal(); blocks = []\n"
                         "    while not it.IsDoneWithTraversal():\n"
                         "        b = it.GetCurrentDataObject(); cd = b.GetCellData()\n"
                         "        arr = {cd.GetArrayName(i): list(cd.GetArray(i).GetTuple(0))\n"
                         "               for i in range(cd.GetNumberOfArrays())}\n"
                         "        blocks.append([b.GetNumberOfPoints(), list(b.GetPoint(0)), arr])\n"
                         "        it.GoToNextItem()\n"
                         "    out.append([t, blocks])\n"
                         "print('JSON' + json.dumps(out))\n")
            p = subprocess.run([pv, "--force-offscreen-rendering", script, xdmf],
                               capture_output=True, text=True)
            line = [ln for ln in p.stdout.splitlines() if ln.startswith("JSON")]
            res = json.loads(line[-1][4:]) if line else []
            # the XDMF 2 reader logs "no caching possible" for geometry behind a HyperSlab: not
            # an error of the file; anything else it logs is
            errs = [ln for ln in p.stderr.splitlines() if "ERR" in ln and
                    "no caching possible" not in ln]
            check(p.returncode == 0 and len(res) == len(frames) and not errs,
                  f"pvpython reads all {len(res)} of {len(frames)} frames {errs[:1]}")
            samples = [int(fr.get("Name").split()[-1]) for fr in frames]
            worst = 0.0
            ok_pv = True
            with h5py.File(h5, "r") as f:
                for (tv, blocks), i in zip(res, samples):
                    ok_pv &= abs(tv - t[i]) < 1e-9 and len(blocks) == 10
                    if len(blocks) != 10:
                        continue
                    sup, legs = blocks[1], blocks[2:]
                    d = [np.abs(np.array(sup[1]) - f["/support/corners"][i, 0]).max(),
                         np.abs(np.array(sup[2]["contact_force_N"]) - f["/contact/force"][i]).max()]
                    for k, (n, p0, arr) in enumerate(legs):
                        c = "ABCDEFGH"[k]
                        ok_pv &= n == K
                        d += [np.abs(np.array(p0) - f[f"/legs/{c}/centerline"][i, 0]).max(),
                              np.abs(np.array(arr["pressure_MPa"]) -
                                     f["/pressure"][i, 12 * k:12 * k + 12]).max(),
                              np.abs(np.array(arr["foot_force_N"]) -
                                     f["/contact/foot_force"][i, k]).max(),
                              abs(arr["stance"][0] - f["/contact/stance"][i, k])]
                    worst = max(worst, max(d))
            check(ok_pv and worst == 0.0 and len(res) > 0,
                  f"pvpython: every frame's points and attributes are the run file's ({worst})")
        else:
            print("skip pvpython (not installed)")
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    print(f"{passed} passed, {failed} failed")
    return 0 if failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
