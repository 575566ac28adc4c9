#!/usr/bin/python3
"""The README's two-body program (apps/examples/two_bodies.cpp) prints what IM1 and IM2 say.

Usage: check_two_body_output.py <example_two_bodies executable>

Oracle: IM1 and IM2 in closed form for a constant force and torque, with the program's own
inputs: x = x0 + v0 t + (g + F/m) t^2 / 2, v = v0 + (g + F/m) t, phi = (tau/I) t^2 / 2,
omega = (tau/I) t; m and I from the shapes (a 1 m box of density 1: 1 kg; a disc of radius
0.5 m: m = pi r^2, I = m r^2 / 2). Checked at t = 1/3 s, before the bodies meet (the box's
right face is at 1.06 m, the ball's left side at 2.17 m). The velocities of a semi-implicit
step under a constant acceleration are exact, so they must agree to the printed rounding; its
positions lag the closed form by a t h / 2 with h the step (at most dt = 1/60 s), which is
the positions' tolerance. A supporting figure for NFR3's usability trial (docs/usability.md),
not its verification: a person's time is not measured here.
"""
import math
import re
import subprocess
import sys

T = 20 / 60          # the program prints every 20 steps of 1/60 s
DT = 1 / 60
G = (0.0, -10.0)     # WorldDef's gravity as the program sets it
ROUND = 0.0005 + 1e-12  # printed with three decimals


def expected():
    box_m = 1.0 * 1.0 * 1.0
    ball_m = math.pi * 0.5 ** 2
    ball_i = ball_m * 0.5 ** 2 / 2
    bodies = {
        "box": {"x0": (0.0, 0.0), "v0": (0.0, 0.0), "a": (G[0] + 10.0 / box_m, G[1]), "alpha": 0.0},
        "ball": {"x0": (3.0, 0.0), "v0": (-1.0, 0.0), "a": G, "alpha": 0.5 / ball_i},
    }
    out = {}
    for name, b in bodies.items():
        pos = [b["x0"][k] + b["v0"][k] * T + 0.5 * b["a"][k] * T * T for k in (0, 1)]
        vel = [b["v0"][k] + b["a"][k] * T for k in (0, 1)]
        lag = [0.5 * abs(b["a"][k]) * T * DT for k in (0, 1)]
        phi = 0.5 * b["alpha"] * T * T
        out[name] = {"x": (pos[0], lag[0] + ROUND), "y": (pos[1], lag[1] + ROUND),
                     "vx": (vel[0], ROUND), "vy": (vel[1], ROUND),
                     "phi": (phi, 0.5 * b["alpha"] * T * DT + ROUND),
                     "omega": (b["alpha"] * T, ROUND)}
    return out


def main():
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    text = subprocess.run([sys.argv[1]], check=True, capture_output=True, text=True).stdout
    want = expected()
    seen, failures = set(), []
    for line in text.splitlines():
        m = re.match(r"t=(\S+) (\w+)\s+(.*)$", line)
        if not m or m.group(1) != "0.333":
            continue
        name = m.group(2)
        got = {k: float(v) for k, v in re.findall(r"(\w+)=\s*(-?[0-9.]+)", m.group(3))}
        seen.add(name)
        for key, (value, tol) in want[name].items():
            err = abs(got[key] - value)
            status = "ok" if err <= tol else "FAIL"
            print(f"{name} {key}: printed {got[key]:.3f}, closed form {value:.4f}, "
                  f"|diff| {err:.4f} <= {tol:.4f}: {status}")
            if err > tol:
                failures.append(f"{name}.{key}")
    if seen != set(want):
        failures.append(f"lines at t=0.333 for {sorted(seen)}, expected {sorted(want)}")
    if failures:
        print("FAILED: " + ", ".join(failures))
        return 1
    print("the two-body program's states at t = 1/3 s agree with IM1 and IM2")
    return 0


if __name__ == "__main__":
    sys.exit(main())
