#!/usr/bin/python3
"""heading_control.py: a feedback controller in Python steers the robot to a commanded heading on
the flat road, through contact and friction only (issue 35's first example;
docs/reference/python.md "Example: steering to a heading").

Usage:
  /usr/bin/python3 tools/python/examples/heading_control.py [--heading DEG] [--t-end S]
      [--kp K] [--kd S] [--legs LEVEL] [--links N] [--rod-tol K] [-o OUT.png] [--csv OUT.csv]

The controller. The shipped gait of the flat road (gaits/flat_road_rod.csv, the scene's) is the
feedforward; its strides from 2 s on repeat with a period of 2 s, so past the table's last
stride (9 s) the controller replays that period (t -> 3 + (t - 3) mod 2). Each side's twelve
legs' chambers get the gait's command times a gain, the same gain for the four legs of a row:
    e = psi_cmd - psi          (rad; psi the support's heading, + towards -z, the A-D side)
    u = kp e - kd w_y          (w_y the support's yaw rate, rad/s), clipped to [-u_max, u_max]
    k_AD = 1 - max(u, 0),  k_EH = 1 - max(-u, 0)
A row that pushes with less pressure takes shorter strides, so the robot yaws towards that
row: e > 0 (turn towards -z) lowers the A-D row's pressures. Only lowered, never raised: the
gait already reaches 0.32 MPa and the calibration table ends at 0.4 MPa, so a gain above 1.24
would leave the range the legs are calibrated for (the library refuses it). The gains are computed between steps from
the state (the support's pose and twist: what an IMU would give); within a step the callback
is a function of time alone (core/crawlsim.h csController), as the library requires. Nothing
moves the support but the legs' contact forces: the controller only changes chamber commands.

Output: a PNG (track from above with the heading, heading against time with the command,
the two gains), a CSV of the track if --csv is given, and a last line
  heading_control: final heading H deg, command C deg, error E deg (within 5 deg: yes|no), ...
Exit status 0 when the final heading is within --tol deg (5) of the command, 2 when it is not,
1 with one line on stderr on bad input or a failed step.
"""

import argparse
import math
import sys
import time

import numpy as np

import crawlsim

GAIT_PERIOD = 2.0    # s: the flat road's gait repeats its strides every 2 s from t = 2 s
GAIT_REPEAT_FROM = 3.0  # s: replayed from here past the table's strides (gaits/flat_road_rod.gait)
GAIT_STRIDES_END = 9.0  # s: the table's last stride ends here (then it vents)


class HeadingController:
    """p_cmd(t) = gait(t') * gain per row; gains from the heading error, updated between steps."""

    def __init__(self, sim, heading_deg, kp, kd, u_max):
        self.psi_cmd = math.radians(heading_deg)
        self.kp, self.kd, self.u_max = kp, kd, u_max
        self.gain = np.ones(sim.nchamber)
        self.rows = (slice(0, 48), slice(48, 96))  # labels 1..48: legs A-D; 49..96: E-H
        self.k = (1.0, 1.0)
        self._pos, self._quat = np.empty(3), np.empty(4)
        self._v, self._w = np.empty(3), np.empty(3)

    def update(self, sim):
        """Between steps: read the support's heading and yaw rate, set the rows' gains."""
        sim.support_pose(self._pos, self._quat)
        sim.support_twist(self._v, self._w)
        psi = math.radians(float(crawlsim.heading_deg(self._quat)))
        e = math.atan2(math.sin(self.psi_cmd - psi), math.cos(self.psi_cmd - psi))
        u = self.kp * e - self.kd * self._w[1]
        u = max(-self.u_max, min(self.u_max, u))
        self.k = (1.0 - max(u, 0.0), 1.0 - max(-u, 0.0))
        self.gain[self.rows[0]] = self.k[0]
        self.gain[self.rows[1]] = self.k[1]
        return psi

    def __call__(self, sim, t, p_cmd):
        """Within a step (csController): the gait's command at t times the rows' gains."""
        if t >= GAIT_STRIDES_END:
            t = GAIT_REPEAT_FROM + math.fmod(t - GAIT_REPEAT_FROM, GAIT_PERIOD)
        sim.gait_command(t, out=p_cmd)
        np.multiply(p_cmd, self.gain, out=p_cmd)


def simulate(args, log=print):
    d = crawlsim.RunDef(scene="flat-road", legs=args.legs, links=args.links, rod_tol=args.rod_tol,
                        conditions=args.conditions)
    sim = crawlsim.Sim(d)
    ctl = HeadingController(sim, args.heading, args.kp, args.kd, args.u_max)
    sim.set_controller(ctl)
    every = max(1, int(round(args.sample / sim.macro_step)))
    n = int(round(args.t_end / sim.macro_step))
    rec = []
    cpu0 = time.process_time()
    psi = 0.0
    for k in range(n + 1):
        psi = ctl.update(sim)
        if k % every == 0 or k == n:
            pos, _ = sim.support_pose()
            rec.append((sim.t, *pos, math.degrees(psi), *ctl.k))
        if k % int(round(1.0 / sim.macro_step)) == 0:
            log(f"heading_control: t = {sim.t:5.2f} s, x = {rec[-1][1]:6.1f} mm, z = "
                f"{rec[-1][3]:6.1f} mm, heading {math.degrees(psi):6.2f} deg, gains A-D "
                f"{ctl.k[0]:.3f}, E-H {ctl.k[1]:.3f}")
        if k < n:
            sim.step()
    cpu = time.process_time() - cpu0
    sim.close()
    return np.array(rec), cpu


def draw(rec, args, out):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    t, x, _, z, psi, kl, kr = rec.T
    fig, ax = plt.subplots(1, 3, figsize=(15, 4.6))
    a = ax[0]
    a.plot(x, z, color="C0", label="support centre")
    for i in range(0, len(t), max(1, len(t) // 12)):
        r = math.radians(psi[i])
        a.annotate("", xy=(x[i] + 20 * math.cos(r), z[i] - 20 * math.sin(r)), xytext=(x[i], z[i]),
                   arrowprops=dict(arrowstyle="->", color="C3", lw=1))
    rc = math.radians(args.heading)
    a.plot([x[-1], x[-1] + 60 * math.cos(rc)], [z[-1], z[-1] - 60 * math.sin(rc)], "k--", lw=1,
           label=f"commanded heading {args.heading:g} deg")
    a.set_xlabel("x (mm, displacement from the start)")
    a.set_ylabel("z (mm)")
    a.invert_yaxis()
    a.set_aspect("equal", adjustable="datalim")
    a.legend(fontsize=8, loc="best")
    a.set_title("(a) track from above (legs A-D on the top side)")
    b = ax[1]
    b.plot(t, psi, color="C3", label="heading")
    b.axhline(args.heading, color="k", ls="--", lw=1, label="command")
    b.axhspan(args.heading - args.tol, args.heading + args.tol, color="0.85", label=f"+-{args.tol:g} deg")
    b.set_xlabel("t (s)")
    b.set_ylabel("heading (deg)")
    b.legend(fontsize=8)
    b.set_title("(b) heading")
    c = ax[2]
    c.plot(t, kl, label="gain, legs A-D")
    c.plot(t, kr, label="gain, legs E-H")
    c.set_xlabel("t (s)")
    c.set_ylabel("gain on the gait's pressures")
    c.legend(fontsize=8)
    c.set_title("(c) the controller's gains")
    fig.suptitle(f"Heading control on the flat road ({args.legs} legs, {args.conditions} "
                 f"conditions): kp {args.kp:g}, kd {args.kd:g} s, gains within 1 +- {args.u_max:g}; "
                 f"final heading {psi[-1]:.2f} deg for {args.heading:g}", fontsize=10)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def main(argv=None):
    ap = argparse.ArgumentParser(prog="heading_control", description=__doc__.split("\n")[0])
    ap.add_argument("--heading", type=float, default=-20.0,
                    help="commanded heading, deg (+ towards -z, the A-D side); default -20")
    ap.add_argument("--t-end", type=float, default=9.0, help="simulated s (default 9)")
    ap.add_argument("--kp", type=float, default=4.0, help="gain per rad of heading error (4)")
    ap.add_argument("--kd", type=float, default=0.0, help="gain per rad/s of yaw rate, s (0)")
    ap.add_argument("--u-max", type=float, default=0.5, help="largest change of a row's gain (0.5)")
    ap.add_argument("--tol", type=float, default=5.0, help="allowed final error, deg (5)")
    ap.add_argument("--legs", default="rod", help="leg level (rod)")
    ap.add_argument("--links", type=float, default=None, help="elements per segment (the scene's)")
    ap.add_argument("--rod-tol", type=float, default=None, help="rod CVODE tolerance factor (1)")
    ap.add_argument("--conditions", default="paper", help="paper (the scene's) or earth")
    ap.add_argument("--sample", type=float, default=0.01, help="recording interval, s (0.01)")
    ap.add_argument("-o", "--out", default="heading_control.png", help="the picture")
    ap.add_argument("--csv", help="write the track (t, x, y, z, heading, gains) to this CSV")
    args = ap.parse_args(argv)
    if not (args.t_end > 0 and args.u_max > 0 and args.u_max < 1 and args.sample > 0):
        print("heading_control: --t-end and --sample must be > 0, --u-max in (0, 1)",
              file=sys.stderr)
        return 1
    try:
        rec, cpu = simulate(args)
    except crawlsim.Error as e:
        print(f"heading_control: {e}", file=sys.stderr)
        return 1
    if args.csv:
        np.savetxt(args.csv, rec, delimiter=",", fmt="%.9g",
                   header="t_s,x_mm,y_mm,z_mm,heading_deg,gain_AD,gain_EH", comments="")
    draw(rec, args, args.out)
    final, err = rec[-1, 4], rec[-1, 4] - args.heading
    ok = abs(err) <= args.tol
    print(f"heading_control: final heading {final:.2f} deg, command {args.heading:g} deg, error "
          f"{err:+.2f} deg (within {args.tol:g} deg: {'yes' if ok else 'no'}); x = {rec[-1, 1]:.1f} mm, "
          f"z = {rec[-1, 3]:.1f} mm at t = {rec[-1, 0]:.2f} s; {cpu:.1f} CPU s; picture {args.out}")
    return 0 if ok else 2


if __name__ == "__main__":
    sys.exit(main())
