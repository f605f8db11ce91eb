#!/usr/bin/python3
"""test_run_plots.py: the run pictures of issue 36 (tools/plot_run.py: footfall diagram, chamber
pressures, foot paths relative to the hips, ground forces per foot; tools/plot_track.py's side
view with the terrain drawn) on small synthetic run files (make_synthetic_h5.py, plus a terrain
with a 40 mm step, root attributes for the title, and for one file per-foot contact).

Checks: every picture is written and opens with matplotlib's image reader at a non-zero size;
the geometric stance (no /contact/stance) is the synthetic feet's truth (on the ground when not
lifted above 1 mm); a file's /contact/stance is taken over the geometry when present; the title
names scene, slope, conditions, legs and calibration; the foot paths relative to the hips
undo the support's attitude (a foot fixed under a turning support keeps its hip offset);
missing per-foot forces and a bad chamber label are one line on stderr and exit 1.
The other pictures of issue 36 item 4: the animation (tools/animate_run.py, the quick start's
GIF: several frames) and tools/quickstart.sh calling it; the FE's deformed shape beside the bend
curve (tools/plot_fe_shape.py) on a synthetic quadratic-tetrahedra VTU of two cubes, one inside
the other (the boundary faces are the two cubes' 12 + 12 triangles, the skin the outer cube's
12, split in four); the held-out grid of tools/plot_calibration.py (rows of two cases, at most
1100 px wide, taller than a strip).
Prints "N passed, N failed"; exits non-zero on any failure.
"""

import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "tools"))
os.environ.setdefault("MPLBACKEND", "Agg")

import h5py  # noqa: E402
import matplotlib.image as mpimg  # noqa: E402
import numpy as np  # noqa: E402

import plot_calibration  # noqa: E402
import plot_fe_shape  # noqa: E402
import plot_run  # noqa: E402

PY = sys.executable
passed = failed = 0


def check(cond, what):
    global passed, failed
    if cond:
        passed += 1
        print(f"ok   {what}")
    else:
        failed += 1
        print(f"FAIL {what}")


def png_opens(path, what):
    try:
        img = mpimg.imread(path)
        check(img.ndim == 3 and img.shape[0] > 0 and img.shape[1] > 0,
              f"{what}: {os.path.basename(path)} opens, {img.shape[1]} x {img.shape[0]} px")
    except Exception as e:  # a missing or broken file
        check(False, f"{what}: {path} opens ({e})")


def make_run(path, with_contact):
    subprocess.run([PY, os.path.join(HERE, "make_synthetic_h5.py"), "run", path, "--n", "181"],
                   check=True, capture_output=True)
    with h5py.File(path, "a") as f:
        # the road (long enough for every foot) and a 40 mm step from x = 240 to 460, 8 corners a box
        boxes = [((-500, -20, -150), (946, 0, 150)), ((240, 0, -150), (460, 40, 150))]
        hexa = [(0, 0, 0), (1, 0, 0), (1, 0, 1), (0, 0, 1), (0, 1, 0), (1, 1, 0), (1, 1, 1), (0, 1, 1)]
        c = [[hi[i] if h[i] else lo[i] for i in range(3)] for lo, hi in boxes for h in hexa]
        f["/terrain/corners"] = np.array(c, float)
        for k, v in (("scene", "obstacle"), ("conditions", "paper"), ("leg_model", "rod"),
                     ("calibration", "FE mode table (...): robot/calibration_fe_leg_modes.h5"),
                     ("calibration_rule", "rbf-pair"), ("links_per_segment", 4.0),
                     ("slope_deg", 7.5)):
            f.attrs[k] = v
        n = f["/time"].shape[0]
        f["/pressure"][:, 21] = np.linspace(0, 0.3, n)  # label 22 = B_II3_O2
        if with_contact:
            st = np.zeros((n, 8))
            st[:, 0] = 1  # A always stands, the others never: unlike the geometry
            f["/contact/stance"] = st
            F = np.zeros((n, 8, 3))
            F[:, 0, 1] = 2.0
            f["/contact/foot_force"] = F


def kuhn_cube(lo, h):
    """A cube [lo, lo + h]^3 as six tetrahedra along its diagonal (Kuhn): points [8,3], cells [6,4]."""
    import itertools
    pts = np.array([[lo + h * ((v >> a) & 1) for a in range(3)] for v in range(8)], float)
    cells = []
    for perm in itertools.permutations(range(3)):
        v, tet = 0, [0]
        for a in perm:
            v |= 1 << a
            tet.append(v)
        cells.append(tet)
    return pts, np.array(cells)


def write_quadratic_vtu(path, parts, shift):
    """A VTU of quadratic tetrahedra (VTK 24) from linear parts [(points, cells)], edge midpoints
    added; the points moved by `shift` (mm), stored as the displacement as fem_output.c does."""
    x, cells10 = [], []
    for pts, cells in parts:
        base = len(x)
        x.extend(pts.tolist())
        mid = {}
        for c in cells:
            g = [base + i for i in c]
            row = list(g)
            for a, b in ((0, 1), (1, 2), (0, 2), (0, 3), (1, 3), (2, 3)):
                key = tuple(sorted((g[a], g[b])))
                if key not in mid:
                    mid[key] = len(x)
                    x.append(((np.array(x[g[a]]) + np.array(x[g[b]])) / 2).tolist())
                row.append(mid[key])
            cells10.append(row)
    x = np.array(x)
    u = np.tile(np.asarray(shift, float), (len(x), 1))
    def arr(v):
        return "\n".join(" ".join(f"{a:.9g}" for a in np.atleast_1d(r)) for r in v)
    with open(path, "w") as f:
        f.write('<?xml version="1.0"?>\n<VTKFile type="UnstructuredGrid" version="0.1">\n'
                f'<UnstructuredGrid>\n<Piece NumberOfPoints="{len(x)}" NumberOfCells="{len(cells10)}">\n'
                f'<Points><DataArray type="Float64" NumberOfComponents="3" format="ascii">\n{arr(x + u)}\n'
                '</DataArray></Points>\n<Cells>\n'
                f'<DataArray type="Int32" Name="connectivity" format="ascii">\n{arr(cells10)}\n</DataArray>\n'
                '<DataArray type="Int32" Name="offsets" format="ascii">\n'
                f'{arr(10 * np.arange(1, len(cells10) + 1))}\n</DataArray>\n'
                '<DataArray type="UInt8" Name="types" format="ascii">\n'
                f'{arr([24] * len(cells10))}\n</DataArray>\n</Cells>\n'
                '<PointData Vectors="displacement"><DataArray type="Float64" Name="displacement" '
                f'NumberOfComponents="3" format="ascii">\n{arr(u)}\n</DataArray></PointData>\n'
                '</Piece>\n</UnstructuredGrid>\n</VTKFile>\n')


def other_pictures(tmp):
    """The animation, the FE shape beside the bend curve and the held-out grid."""
    from PIL import Image
    run = os.path.join(tmp, "run.h5")
    with h5py.File(run, "a") as f:  # the support's box (animate_run.py draws it): 240 x 40 x 150 mm
        box = np.array([[sx * 120, sy * 20, sz * 75] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)], float)
        f["/support/corners"] = f["/support/position"][:][:, None, :] + box[None, :, :]
    gif = os.path.join(tmp, "run.gif")
    out = subprocess.run([PY, os.path.join(ROOT, "tools", "animate_run.py"), run, "-o", gif,
                          "--fps", "10", "--speed", "2"], capture_output=True, text=True)
    check(out.returncode == 0, f"animate_run.py exits 0 ({out.stderr.strip()[:200]})")
    try:
        with Image.open(gif) as im:
            n = getattr(im, "n_frames", 1)
            check(im.size[0] > 0 and im.size[1] > 0 and n > 1,
                  f"the animation opens: {im.size[0]} x {im.size[1]} px, {n} frames")
    except Exception as e:
        check(False, f"the animation {gif} opens ({e})")
    with open(os.path.join(ROOT, "tools", "quickstart.sh")) as f:
        calls = [l for l in f.read().splitlines() if "animate_run.py" in l and "echo" not in l
                 and not l.lstrip().startswith("#")]
    check(any("-o out/flat_road_paper.gif" in l for l in calls),
          f"quickstart.sh writes out/flat_road_paper.gif itself ({calls})")

    # the FE shape: an outer cube (0..10 mm) with a sealed inner one (4..6 mm) as its "chamber"
    vtu = os.path.join(tmp, "bend.vtu")
    write_quadratic_vtu(vtu, [kuhn_cube(0.0, 10.0), kuhn_cube(4.0, 2.0)], (0.0, 0.0, 3.0))
    mesh = plot_fe_shape.load_vtu(vtu)
    tri, full = plot_fe_shape.boundary_faces(mesh["cells"])
    check(tri.shape == (24, 3) and full.shape == (24, 6), f"boundary faces of two cubes: {tri.shape[0]} (24)")
    skin = plot_fe_shape.outer_skin(mesh["x"] - mesh["u"], tri)
    outer = np.all((mesh["x"] - mesh["u"])[tri] % 10.0 == 0.0, axis=(1, 2))
    check(skin.sum() == 12 and np.array_equal(skin, outer), f"the skin is the outer cube's 12 faces ({skin.sum()})")
    verts, mag, nf = plot_fe_shape.surface_triangles(mesh, False)
    check(verts.shape == (48, 3, 3) and nf == 12 and np.allclose(mag, 3.0),
          f"skin faces split in four: {verts.shape[0]} triangles, |u| {mag.min():.3g}..{mag.max():.3g} mm")
    bend = os.path.join(tmp, "bend.h5")
    subprocess.run([PY, os.path.join(HERE, "make_synthetic_h5.py"), "bend", bend], check=True,
                   capture_output=True)
    shape_png = os.path.join(tmp, "shape.png")
    out = subprocess.run([PY, os.path.join(ROOT, "tools", "plot_fe_shape.py"), bend, "-o", shape_png],
                         capture_output=True, text=True)
    check(out.returncode == 0, f"plot_fe_shape.py exits 0 ({out.stderr.strip()[:200]})")
    png_opens(shape_png, "FE shape beside the bend curve")
    bad = os.path.join(tmp, "bad.vtu")
    with open(bad, "w") as f:
        f.write("<VTKFile><UnstructuredGrid><Piece NumberOfPoints='4'>")
    out = subprocess.run([PY, os.path.join(ROOT, "tools", "plot_fe_shape.py"), bend, "--vtu", bad,
                          "-o", os.path.join(tmp, "bad.png")], capture_output=True, text=True)
    check(out.returncode == 1 and out.stderr.count("\n") == 1 and "bad.vtu" in out.stderr,
          f"a broken VTU: {out.stderr.strip()}")

    # the held-out grid: 9 held-out and symmetry cases in rows of two
    table, pred = os.path.join(tmp, "cal.h5"), os.path.join(tmp, "pred.h5")
    for kind, path in (("caltable", table), ("calpred", pred)):
        subprocess.run([PY, os.path.join(HERE, "make_synthetic_h5.py"), kind, path], check=True,
                       capture_output=True)
    check(plot_calibration.holdout_layout(9, 2) == (5, 2) and plot_calibration.holdout_layout(1, 2) == (1, 1),
          "held-out layout: 9 cases in 5 rows of 2, one case alone")
    caldir = os.path.join(tmp, "cal")
    out = subprocess.run([PY, os.path.join(ROOT, "tools", "plot_calibration.py"), table, "--model",
                          pred, "-o", caldir, "--only", "holdout"], capture_output=True, text=True)
    check(out.returncode == 0 and os.listdir(caldir) == ["calibration_holdout.png"],
          f"plot_calibration --only holdout writes that picture alone ({out.stderr.strip()[:200]})")
    png = os.path.join(caldir, "calibration_holdout.png")
    png_opens(png, "held-out grid")
    try:
        h, w = mpimg.imread(png).shape[:2]
        check(w <= 1100 and h >= w, f"held-out grid {w} x {h} px: at most 1100 wide, not a strip")
    except Exception as e:
        check(False, f"held-out grid size ({e})")


def main():
    with tempfile.TemporaryDirectory() as tmp:
        os.environ["MPLCONFIGDIR"] = os.path.join(tmp, "mpl")
        run = os.path.join(tmp, "run.h5")
        make_run(run, False)
        r = plot_run.load_run(run)
        # the title from the root attributes
        for word in ("scene obstacle (slope 7.5 deg)", "conditions paper", "legs rod (4 per segment)",
                     "calibration calibration_fe_leg_modes.h5 (rbf-pair)"):
            check(word in r["title"], f"title names '{word}': {r['title']}")
        # geometric stance is the synthetic truth: a foot stands where it is not lifted (on the
        # road alone: the synthetic feet ignore the step)
        road = dict(r, terrain=r["terrain"][:8])
        st, source = plot_run.stance_of(road, 1.0)
        foot_y = r["legs"][:, :, -1, 1]
        truth = foot_y <= 1.0
        check(st.shape == (r["t"].shape[0], 8) and np.array_equal(st, truth) and 0 < st.mean() < 1,
              f"geometric stance = feet on the ground ({st.mean():.3f} of samples; {source})")
        # over the step the ground is 40 mm higher: a foot at y = 39.5 there stands, at 41.5 not
        top = plot_run.terrain_top(r["terrain"], np.array([300.0, 300.0, 100.0]),
                                   np.array([0.0, 0.0, 0.0]))
        check(np.array_equal(top, [40.0, 40.0, 0.0]), f"terrain top under (300, 0) and (100, 0): {top}")
        # relative foot paths undo the support's attitude: rotate a vector into a frame turned
        # by 30 deg about z and back
        q = np.array([np.cos(np.pi / 12), 0, 0, np.sin(np.pi / 12)])
        v = np.array([1.0, 0.0, 0.0])
        back = plot_run.quat_rotate_inv(q, np.array([np.cos(np.pi / 6), np.sin(np.pi / 6), 0.0]))
        check(np.allclose(back, v, atol=1e-12), f"a hip offset turned by the support comes back: {back}")
        out = subprocess.run([PY, os.path.join(ROOT, "tools", "plot_run.py"), run,
                              "--chambers", "1,22", "--out-prefix", os.path.join(tmp, "a")],
                             capture_output=True, text=True)
        check(out.returncode == 0, f"plot_run.py exits 0 ({out.stderr.strip()[:200]})")
        for kind in ("footfall", "pressures", "feet"):
            png_opens(os.path.join(tmp, f"a_{kind}.png"), kind)
        out = subprocess.run([PY, os.path.join(ROOT, "tools", "plot_track.py"), run, "-o",
                              os.path.join(tmp, "track.png"), "--reference", "obstacle",
                              "--times", "0,4"], capture_output=True, text=True)
        check(out.returncode == 0, f"plot_track.py with the terrain exits 0 ({out.stderr.strip()[:200]})")
        png_opens(os.path.join(tmp, "track.png"), "side view with the step")
        # no per-foot forces: one line, exit 1
        out = subprocess.run([PY, os.path.join(ROOT, "tools", "plot_run.py"), run, "--kind", "forces",
                              "--out-prefix", os.path.join(tmp, "b")], capture_output=True, text=True)
        check(out.returncode == 1 and out.stderr.count("\n") == 1 and "foot_force" in out.stderr,
              f"forces without /contact/foot_force: {out.stderr.strip()}")
        out = subprocess.run([PY, os.path.join(ROOT, "tools", "plot_run.py"), run, "--chambers", "97"],
                             capture_output=True, text=True)
        check(out.returncode == 2 and "--chambers must be in 1..96" in out.stderr,
              "a chamber label beyond 96 is refused")
        # the run's own stance and forces, when the file has them
        run2 = os.path.join(tmp, "run2.h5")
        make_run(run2, True)
        r2 = plot_run.load_run(run2)
        st2, source2 = plot_run.stance_of(r2, 1.0)
        check(st2[:, 0].all() and not st2[:, 1:].any() and "/contact/stance" in source2,
              f"/contact/stance taken over the geometry ({source2})")
        out = subprocess.run([PY, os.path.join(ROOT, "tools", "plot_run.py"), run2, "--kind",
                              "footfall,forces", "--out-prefix", os.path.join(tmp, "c")],
                             capture_output=True, text=True)
        check(out.returncode == 0, f"plot_run.py footfall,forces exits 0 ({out.stderr.strip()[:200]})")
        png_opens(os.path.join(tmp, "c_forces.png"), "forces")
        png_opens(os.path.join(tmp, "c_footfall.png"), "footfall from /contact/stance")
        other_pictures(tmp)
    print(f"{passed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
