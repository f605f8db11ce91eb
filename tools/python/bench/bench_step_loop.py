#!/usr/bin/python3
"""bench_step_loop.py: the cost of a Python loop of single steps against the same run from C
(issue 35: at most 1.2x), in one process (docs/reference/python.md "Cost of a Python loop").

Usage:
  /usr/bin/python3 tools/python/bench/bench_step_loop.py [--steps 10000] [--chunk 1000]
      [--legs rod] [--links N] [--rod-tol K] [--controller]

Three simulations of the same definition (the flat road's gait) advance together:
  C       one call to cs_simRunUntil per chunk (the loop in C);
  Python  `for _ in range(chunk): sim.step()` (one ctypes call per macro step);
  ctl     with --controller: the Python loop plus a Python controller that replays the gait
          (sim.gait_command(t, out=p)), called by the pneumatic integrator at every inner time.
They take turns chunk by chunk, so a change of the machine's load falls on all of them alike;
each one's CPU time (time.process_time, the process's user + system time) is summed over its
chunks. All end in the same state bit for bit (checked: the same work was done). Prints each
total, the ratios to C, the overhead per step in microseconds and the machine's load.
"""

import argparse
import os
import sys
import time

import numpy as np

import crawlsim


def main(argv=None):
    ap = argparse.ArgumentParser(prog="bench_step_loop", description=__doc__.split("\n")[0])
    ap.add_argument("--steps", type=int, default=10000, help="macro steps (10000)")
    ap.add_argument("--chunk", type=int, default=1000, help="steps per turn (1000)")
    ap.add_argument("--legs", default="rod")
    ap.add_argument("--links", type=float, default=None)
    ap.add_argument("--rod-tol", type=float, default=None)
    ap.add_argument("--controller", action="store_true",
                    help="also time a Python controller replaying the gait")
    args = ap.parse_args(argv)
    if args.steps < 1 or args.chunk < 1:
        print("bench_step_loop: --steps and --chunk must be >= 1", file=sys.stderr)
        return 1
    try:
        d = crawlsim.RunDef(scene="flat-road", legs=args.legs, links=args.links,
                            rod_tol=args.rod_tol)
        sims = {"C": crawlsim.Sim(d), "Python": crawlsim.Sim(d)}
        if args.controller:
            sims["ctl"] = crawlsim.Sim(d)
            sims["ctl"].set_controller(lambda s, t, p: s.gait_command(t, out=p))
        h = sims["C"].macro_step
        cpu = dict.fromkeys(sims, 0.0)
        done = 0
        while done < args.steps:
            n = min(args.chunk, args.steps - done)
            t_target = (done + n) * h
            for name, s in sims.items():
                c0 = time.process_time()
                if name == "C":
                    s.run_until(t_target)
                else:
                    for _ in range(n):
                        s.step()
                cpu[name] += time.process_time() - c0
            done += n
        ref = sims["C"].get_state()
        same = {name: bool(np.array_equal(s.get_state(), ref)) for name, s in sims.items()}
        steps = {name: s.steps for name, s in sims.items()}
    except crawlsim.Error as e:
        print(f"bench_step_loop: {e}", file=sys.stderr)
        return 1
    load = os.getloadavg()
    print(f"bench_step_loop: {args.steps} macro steps of {h * 1e3:g} ms ({args.steps * h:g} s "
          f"simulated), flat road, legs {args.legs} (links {args.links or 'the scene'}, rod-tol "
          f"{args.rod_tol or 1}), in chunks of {args.chunk}; load average {load[0]:.2f} "
          f"{load[1]:.2f} {load[2]:.2f} on {os.cpu_count()} cores; library {crawlsim.library_path()}")
    for name in sims:
        print(f"  {name:7s} CPU {cpu[name]:8.3f} s  ({cpu[name] / args.steps * 1e6:8.1f} us per step, "
              f"{steps[name]} steps, same final state as C: {'yes' if same[name] else 'NO'})")
    for name in sims:
        if name != "C":
            print(f"bench_step_loop: {name} / C = {cpu[name] / cpu['C']:.3f} (overhead "
                  f"{(cpu[name] - cpu['C']) / args.steps * 1e6:+.1f} us per step)")
    return 0 if all(same.values()) else 1


if __name__ == "__main__":
    sys.exit(main())
