#!/usr/bin/env python3
"""draw_robot.py: a labelled drawing of the crawling robot for the manual (docs/robot.png).

    /usr/bin/python3 tools/draw_robot.py [-o docs/robot.png]

Three views, to scale, from the conventions of docs/reference.md:
  (a) top view (looking down, -y): the 210 x 145 mm support, the hips of legs A-H (A-D at -z,
      E-H at +z, each row numbered front (+x) to back; l_EF = 50 mm along a row, l_AE = 130 mm
      between rows), the world frame x (crawl), y (up, out of the page), z (lateral);
  (b) side view of one hanging leg (`leg` actuator: segments II1, II2, II3 of S = 50 mm, solid
      joints LS12 = LS23 = 8 mm, foot at the end of II3);
  (c) a segment's cross-section seen from the hip (side 2a = 15 mm, fillet r2 = 2 mm, chambers
      Omega1..Omega4 of radius r1 = 2 mm at (+-b, +-b), b = 4 mm, in the leg frame e1 = +x,
      e2 = +z, drawn in the same orientation as the top view),
and the chamber label formula 12 k + 4 (s - 1) + j with the paper's four check labels.
Geometry is drawn from the numbers above (the paper's and the project's conventions), not read
from the code. Uses Debian's /usr/bin/python3 (python3-matplotlib).
"""

import argparse

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.patches import Circle, FancyBboxPatch, Rectangle  # noqa: E402

LEGS = "ABCDEFGH"
SUPPORT_X, SUPPORT_Z, SUPPORT_Y = 210.0, 145.0, 10.0  # mm (support box)
L_EF, L_AE = 50.0, 130.0  # mm: spacing along a row, between rows
S, LS = 50.0, 8.0  # mm: segment length, solid joint length (`leg` actuator)
A_HALF, B, R1, R2 = 7.5, 4.0, 2.0, 2.0  # mm: half side a, chamber offset b, radii r1, r2
# chamber centres in the leg frame (e1, e2) (docs/reference.md, "The actuator")
CHAMBERS = {1: (B, B), 2: (B, -B), 3: (-B, -B), 4: (-B, B)}


def label(k, s, j):
    """Chamber label 1..96 of leg k = 0..7 (A..H), segment s = 1..3, chamber j = 1..4."""
    return 12 * k + 4 * (s - 1) + j


def hip(k):
    """Hip of leg k in the support frame (x, z), mm: row 0 = A..D at -z, column 0 = front."""
    row, col = divmod(k, 4)
    return (1.5 - col) * L_EF, (-0.5 if row == 0 else 0.5) * L_AE


def arrow(ax, x, y, dx, dy, text, fontsize=11):
    """An axis arrow from (x, y) by (dx, dy), its name just past the head."""
    ax.annotate("", xy=(x + dx, y + dy), xytext=(x, y),
                arrowprops=dict(arrowstyle="-|>", lw=1.6, color="k"))
    ha = "left" if dx > 0 else "center"
    # below the head when the arrow points down the page, above it when it points up
    va = "center" if dx > 0 else ("top" if (dy > 0) == ax.yaxis_inverted() else "bottom")
    if dx > 0:
        pos = (x + dx * 1.08, y)
    else:
        pos = (x, y + dy * 1.12)
    ax.text(*pos, text, ha=ha, va=va, fontsize=fontsize)


def top_view(ax):
    """(a) the support and the hips from above; z points down the page (right-handed, y up)."""
    ax.add_patch(Rectangle((-SUPPORT_X / 2, -SUPPORT_Z / 2), SUPPORT_X, SUPPORT_Z,
                           fc="#dde6f0", ec="#345", lw=1.5))
    for k in range(8):
        x, z = hip(k)
        ax.add_patch(Rectangle((x - A_HALF, z - A_HALF), 2 * A_HALF, 2 * A_HALF,
                               fc="#f4b183", ec="#a0522d", lw=1.2))
        ax.text(x, z + (-17 if k < 4 else 17), LEGS[k], ha="center", va="center",
                fontsize=14, fontweight="bold")
        ax.text(x, z, f"k={k}", ha="center", va="center", fontsize=6)
    # spacings
    xa, za = hip(0)
    xb, _ = hip(1)
    ax.annotate("", xy=(xb, za - 28), xytext=(xa, za - 28),
                arrowprops=dict(arrowstyle="<->", lw=0.8))
    ax.text((xa + xb) / 2, za - 33, "l_EF = 50", ha="center", va="bottom", fontsize=8)
    _, ze = hip(4)
    xd = hip(3)[0] - 25
    ax.annotate("", xy=(xd, ze), xytext=(xd, za), arrowprops=dict(arrowstyle="<->", lw=0.8))
    ax.text(xd - 3, 0, "l_AE = 130", ha="right", va="center", fontsize=8, rotation=90)
    ax.text(0, 0, "support\n210 x 145 mm", ha="center", va="center", fontsize=9, color="#345")
    ax.text(SUPPORT_X / 2 + 6, 0, "front", ha="left", va="center", fontsize=9, rotation=-90)
    # world frame: x right, z down the page, y out of the page (towards the reader)
    ax.set_xlim(-SUPPORT_X / 2 - 75, SUPPORT_X / 2 + 25)
    ax.set_ylim(SUPPORT_Z / 2 + 85, -SUPPORT_Z / 2 - 45)  # z grows downwards on the page
    ox, oz = -SUPPORT_X / 2 - 40, SUPPORT_Z / 2 + 35
    arrow(ax, ox, oz, 35, 0, "x (crawl)")
    arrow(ax, ox, oz, 0, 30, "z (lateral)")
    ax.add_patch(Circle((ox, oz), 3.5, fc="white", ec="k", lw=1.2))
    ax.add_patch(Circle((ox, oz), 1.0, fc="k"))
    ax.text(ox - 6, oz - 6, "y (up, towards you)", ha="left", va="bottom", fontsize=10)
    ax.text(0, -SUPPORT_Z / 2 - 32, "hips on the support's underside", ha="center",
            fontsize=8, color="#a0522d")
    ax.set_aspect("equal")
    ax.axis("off")
    ax.set_title("(a) top view: legs A-H under the support", fontsize=11)


def side_view(ax):
    """(b) one leg hanging from its hip, seen from the side (x right, y up)."""
    w = 2 * A_HALF
    ax.add_patch(Rectangle((-40, 0), 80, SUPPORT_Y, fc="#dde6f0", ec="#345", lw=1.5))
    ax.text(0, SUPPORT_Y / 2, "support", ha="center", va="center", fontsize=8, color="#345")
    y = 0.0
    parts = [("II1", S), ("LS12", LS), ("II2", S), ("LS23", LS), ("II3", S)]
    for name, length in parts:
        seg = name.startswith("II")
        ax.add_patch(FancyBboxPatch((-A_HALF, y - length), w, length,
                                    boxstyle="round,pad=0,rounding_size=2",
                                    fc="#f4b183" if seg else "#c9c9c9",
                                    ec="#a0522d" if seg else "#666", lw=1.2))
        if seg:
            # two of the four chambers are seen in this cut (x = +-b), each c = 5 mm short of
            # the segment's end faces
            for cx in (-B, B):
                ax.add_patch(Rectangle((cx - R1, y - length + 5), 2 * R1, length - 10,
                                       fc="white", ec="#a0522d", lw=0.6))
            ax.text(A_HALF + 6, y - length / 2, f"{name}\nS = {length:.0f} mm", ha="left",
                    va="center", fontsize=9)
        else:
            ax.text(A_HALF + 6, y - length / 2, f"joint {name} = {length:.0f} mm", ha="left",
                    va="center", fontsize=7, color="#444")
        y -= length
    ax.add_patch(Rectangle((-A_HALF, y - 1.5), w, 1.5, fc="#555", ec="#555"))
    ax.text(A_HALF + 6, y + 5, "foot (end of II3)", ha="left", va="center", fontsize=8)
    ax.plot([-60, 60], [y - 1.5, y - 1.5], color="#7a6a53", lw=2)
    ax.text(-58, y - 6, "terrain", fontsize=8, color="#7a6a53", va="top")
    ax.text(-A_HALF - 4, -2, "hip", ha="right", va="top", fontsize=8)
    ax.text(-A_HALF - 4, -88, "leg = 166 mm\n(fibres wound on\nII1-II3 only)", ha="right",
            va="center", fontsize=7, color="#444")
    ax.set_xlim(-75, 75)
    ax.set_ylim(-185, 20)
    arrow(ax, -50, -150, 20, 0, "x", fontsize=10)
    arrow(ax, -50, -150, 0, 20, "y", fontsize=10)
    ax.set_aspect("equal")
    ax.axis("off")
    ax.set_title("(b) one leg, side view", fontsize=11)


def section_view(ax):
    """(c) a segment's cross-section seen from the hip: e1 = +x right, e2 = +z down the page."""
    ax.add_patch(FancyBboxPatch((-A_HALF, -A_HALF), 2 * A_HALF, 2 * A_HALF,
                                boxstyle=f"round,pad=0,rounding_size={R2}",
                                fc="#f4b183", ec="#a0522d", lw=1.5))
    for j, (e1, e2) in CHAMBERS.items():
        ax.add_patch(Circle((e1, e2), R1, fc="white", ec="#a0522d", lw=1.2))
        ax.text(e1, e2, f"Ω{j}", ha="center", va="center", fontsize=10, fontweight="bold")
    ax.set_xlim(-16, 16)
    ax.set_ylim(17, -16)  # e2 (= +z) grows downwards, as in the top view
    arrow(ax, -A_HALF - 6, -A_HALF - 6, 6, 0, "e1 = +x", fontsize=8)
    arrow(ax, -A_HALF - 6, -A_HALF - 6, 0, 6, "e2 = +z", fontsize=8)
    ax.text(0, A_HALF + 3.5, "side 2a = 15, b = 4, r1 = 2, r2 = 2 (mm)", ha="center",
            va="center", fontsize=7)
    ax.text(0, A_HALF + 6.5, "Ω1&Ω2 bend the segment towards Ω3&Ω4 (-e1)", ha="center",
            va="center", fontsize=7)
    ax.set_aspect("equal")
    ax.axis("off")
    ax.set_title("(c) cross-section from the hip (e3 down the leg)", fontsize=10)


def formula(ax):
    """The label formula and the paper's check labels."""
    checks = [("B", 1, 3, 2), ("H", 7, 2, 3), ("C", 2, 1, 4), ("F", 5, 3, 2)]
    lines = ["chamber label = 12 k + 4 (s - 1) + j",
             "k = 0..7 for legs A..H,  s = 1..3 for II1..II3,",
             "j = 1..4 for Ω1..Ω4   (96 chambers)", ""]
    for name, k, s, j in checks:
        lines.append(f"{label(k, s, j):2d} = {name}-II{s}-Ω{j}")
    lines += ["", "gait CSV column: label or name,", "e.g. 22 or B_II3_O2"]
    ax.text(0.0, 1.0, "\n".join(lines), ha="left", va="top", fontsize=10, family="DejaVu Sans",
            transform=ax.transAxes)
    ax.axis("off")


def main():
    ap = argparse.ArgumentParser(description="labelled drawing of the crawling robot")
    ap.add_argument("-o", "--out", default="docs/robot.png", help="output PNG")
    args = ap.parse_args()
    fig = plt.figure(figsize=(12, 7.2))
    gs = fig.add_gridspec(2, 3, width_ratios=[2.4, 1.0, 1.2], height_ratios=[1.0, 1.0])
    top_view(fig.add_subplot(gs[:, 0]))
    side_view(fig.add_subplot(gs[:, 1]))
    section_view(fig.add_subplot(gs[0, 2]))
    formula(fig.add_subplot(gs[1, 2]))
    fig.suptitle("crawlsim's robot: 8 legs x 3 segments x 4 chambers (units mm)", fontsize=13)
    fig.tight_layout()
    fig.savefig(args.out, dpi=110)
    print(f"draw_robot.py: wrote {args.out}")


if __name__ == "__main__":
    main()
