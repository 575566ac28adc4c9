#!/usr/bin/python3
"""The README's first program (apps/examples/falling_box.cpp) prints what the physics says.

Usage: check_falling_box_output.py <example_falling_box executable>

Oracle, with the program's own inputs (g = 9.81 m/s^2, a 1 m box released at rest at y = 4 m
above ground whose top face is at y = 0.5 m, steps of h = 1/60 s):
  * at t = 0.5 s the box is still falling (it meets the ground at sqrt(2 * 3 / g) = 0.78 s):
    IM1 in closed form, vy = -g t, which a semi-implicit step under constant acceleration gives
    exactly (to the printed rounding), and y = 4 - g t^2 / 2, which its positions trail by
    g t h / 2;
  * from t = 1.5 s on it rests on the ground: y = 0.5 + 0.5 = 1 m, less the soft contact's
    static sag (g / omega^2 with omega = 2 pi 45 Hz, 0.12 mm, IM7), within 1 mm, and vy = 0
    to the printed rounding (restitution 0: it does not bounce).
A supporting check of a quoted program; its physics is verified by the IM1 and IM7 tests.
"""
import math
import re
import subprocess
import sys

G, H = 9.81, 1.0 / 60.0
ROUND = 0.00005 + 1e-12  # four decimals


def main():
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    out = subprocess.run([sys.argv[1]], check=True, capture_output=True, text=True).stdout
    rows = {float(t): (float(y), float(vy)) for t, y, vy in re.findall(
        r"t=(\S+) s  y=(\S+) m  vy=(\S+) m/s", out)}
    if sorted(rows) != [0.5, 1.0, 1.5, 2.0]:
        print("unexpected output:\n" + out)
        return 1
    failures = []
    y, vy = rows[0.5]
    t = 0.5
    if abs(vy - (-G * t)) > ROUND:
        failures.append(f"t=0.5: vy {vy}, closed form {-G * t}")
    if abs(y - (4.0 - 0.5 * G * t * t)) > 0.5 * G * t * H + ROUND:
        failures.append(f"t=0.5: y {y}, closed form {4.0 - 0.5 * G * t * t}")
    for t in (1.5, 2.0):
        y, vy = rows[t]
        if abs(y - 1.0) > 1e-3 or not math.isfinite(y):
            failures.append(f"t={t}: y {y}, at rest on the ground 1.0")
        if abs(vy) > ROUND:
            failures.append(f"t={t}: vy {vy}, at rest 0")
    for f in failures:
        print(f)
    print("falling_box: " + ("FAILED" if failures else "free fall and rest as the closed form"))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
