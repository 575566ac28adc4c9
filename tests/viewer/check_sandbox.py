#!/usr/bin/env python3
"""Checks the live sandbox (build-wasm/sandbox.html, scripts/build_wasm.sh) in headless Chromium.

    check_sandbox.py --cli build/apps/cli/tamias2d [--page build-wasm/sandbox.html]
                     [--shot FILE.png] [CASE...]

A CASE is "scene.json:STEPS:EVERY" (default: pyramid20.json:120:20). For each case the page
loads the example scene and steps it in the browser; after every EVERY steps, every body's
state (x, y, phi, vx, vy, omega: the doubles World::state returns) is read back from the
WebAssembly module and compared bit for bit with `tamias2d run --every EVERY`'s CSV of the
same scene (the CSV's numbers are shortest round-trip text: they read back as the same
doubles). A difference is reported precisely (step, body, value, both doubles in hex, their
distance in ulps) and fails the check.

Then, on pyramid20: the page requests nothing but itself, raises no script error, runs when
played, drops a box where a click falls, pulls a body with the mouse (a target joint: the body
moves towards the cursor), follows a change of gravity, and a screenshot shows the bodies (the
pixels at their projected centres differ from the background).

Exit status: 0 when every check passes, 1 when one fails, 77 when the page or Chromium is
missing (CTest's SKIP_RETURN_CODE), 2 for a bad command line.
"""
from __future__ import annotations

import argparse
import csv
import os
import struct
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from check_player import HEIGHT, SKIP, WIDTH, Browser, CdpError, find_chromium, hex_rgb, page_errors  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
KEYS = ("x", "y", "phi", "vx", "vy", "omega")


def bits(v: float) -> int:
    return struct.unpack("<q", struct.pack("<d", v))[0]


def ulps(a: float, b: float) -> int:
    """Distance in units in the last place (doubles of the same sign)."""
    ia, ib = bits(a), bits(b)
    if ia < 0:
        ia = -(ia & 0x7FFFFFFFFFFFFFFF)
    if ib < 0:
        ib = -(ib & 0x7FFFFFFFFFFFFFFF)
    return abs(ia - ib)


def hexd(v: float) -> str:
    return f"{bits(v) & 0xFFFFFFFFFFFFFFFF:016x}"


def native_frames(cli, scene, steps, every, work):
    out = work / f"{scene.stem}.csv"
    subprocess.run([cli, "run", str(scene), "--steps", str(steps), "--every", str(every), "-o", str(out)],
                   check=True)
    frames = {}
    with open(out, newline="") as fh:
        for row in csv.DictReader(fh):
            frames.setdefault(int(row["step"]), []).append(row)
    return frames


def compare(browser, cli, case, work):
    name, steps, every = case
    scene = ROOT / "examples" / "scenes" / name
    frames = native_frames(cli, scene, steps, every, work)
    if not browser.evaluate(f"tamiasSandbox.load({name!r})"):
        raise AssertionError(f"{name}: the page did not load it: {browser.evaluate('tamiasSandbox.error()')}")
    differences, compared, first = [], 0, None
    done = 0
    t0 = time.monotonic()
    for step in sorted(frames):
        if step > done and not browser.evaluate(f"tamiasSandbox.step({step - done})", timeout=300):
            raise AssertionError(f"{name}: step {step}: {browser.evaluate('tamiasSandbox.error()')}")
        done = step
        states = browser.evaluate("tamiasSandbox.states()")
        rows = frames[step]
        if len(states) != 6 * len(rows):
            raise AssertionError(f"{name}: step {step}: {len(states) // 6} bodies in the page, {len(rows)} in the CSV")
        for b, row in enumerate(rows):
            for k, key in enumerate(KEYS):
                native, page = float(row[key]), states[6 * b + k]
                compared += 1
                if bits(native) != bits(page):
                    d = (step, b, row["name"], key, native, page)
                    differences.append(d)
                    first = first or d
    seconds = time.monotonic() - t0
    if differences:
        s, b, body, key, native, page = first
        bodies = len({(d[0], d[1]) for d in differences})
        raise AssertionError(
            f"{name}: {len(differences)} of {compared} doubles differ ({bodies} body states); the first at "
            f"step {s}, body {b} '{body}', {key}: native {native!r} ({hexd(native)}), "
            f"WebAssembly {page!r} ({hexd(page)}), {ulps(native, page)} ulp")
    last = max(frames)
    return (f"{name}: {compared} doubles over {len(frames)} frames to step {last} bitwise equal to the "
            f"native CLI ({seconds:.1f} s in the page); state hash at step {last}: "
            f"{browser.evaluate('tamiasSandbox.stateHash()')}")


def check_pixels(browser, image, background, label):
    sample = browser.evaluate("""(() => {
        const s = tamiasSandbox, out = [];
        for (let b = 0; b < s.bodyCount(); b++) {
          const st = s.state(b), c = s.toScreen(st.x, st.y), e = s.toScreen(st.x + s.radius(b), st.y);
          out.push([b, s.type(b), c.x, c.y, Math.abs(e.x - c.x)]);
        }
        return out; })()""")
    chosen = [s for s in sample if s[1] != "static" and s[4] >= 3
              and 2 <= s[2] < WIDTH - 2 and 2 <= s[3] < HEIGHT - 2]
    if not chosen:
        raise AssertionError(f"{label}: no body is on the screen")
    chosen = chosen[::max(1, len(chosen) // 12)][:12]
    missing = []
    for b, _, x, y, _ in chosen:
        near = [image.getpixel((int(x) + dx, int(y) + dy)) for dx in (-1, 0, 1) for dy in (-1, 0, 1)]
        if not any(sum(abs(p[i] - background[i]) for i in range(3)) > 30 for p in near):
            missing.append(f"body {b} at ({x:.0f}, {y:.0f})")
    if missing:
        raise AssertionError(f"{label}: background colour where bodies should be: {', '.join(missing)}")
    return len(chosen)


def mouse(browser, kind, x, y, **extra):
    browser.call("Input.dispatchMouseEvent", {"type": kind, "x": x, "y": y, **extra})
    browser.evaluate("new Promise(r => requestAnimationFrame(() => requestAnimationFrame(r)))")


def check_interaction(browser, shot):
    s = "tamiasSandbox"
    browser.evaluate(f"{s}.load('pyramid20.json')")
    # Played, it runs in real time.
    browser.evaluate(f"{s}.play()")
    time.sleep(1.0)
    browser.evaluate(f"{s}.pause()")
    played = browser.evaluate(f"{s}.steps()")
    if played < 10:
        raise AssertionError(f"sandbox: {played} steps after playing for 1 s")
    # A click on empty space drops a box there.
    before = browser.evaluate(f"{s}.bodyCount()")
    at = browser.evaluate(f"{s}.toScreen(14, 6)")
    mouse(browser, "mousePressed", at["x"], at["y"], button="left", buttons=1, clickCount=1)
    mouse(browser, "mouseReleased", at["x"], at["y"], button="left", buttons=0, clickCount=1)
    if browser.evaluate(f"{s}.bodyCount()") != before + 1:
        raise AssertionError("sandbox: a click on empty space dropped no box")
    box = browser.evaluate(f"{s}.state({before})")
    if abs(box["x"] - 14) > 0.05 or abs(box["y"] - 6) > 0.05 or browser.evaluate(f"{s}.type({before})") != "dynamic":
        raise AssertionError(f"sandbox: the dropped box is at ({box['x']}, {box['y']}), not under the click (14, 6)")
    browser.evaluate(f"{s}.step(30)")
    if not browser.evaluate(f"{s}.state({before}).y") < 6 - 0.5 * 10 * 0.25:
        raise AssertionError("sandbox: the dropped box does not fall")
    # Dragging the top box pulls it towards the cursor (a target joint), 3 m to the right.
    top = before - 1
    start = browser.evaluate(f"{s}.state({top})")
    at = browser.evaluate(f"{s}.toScreen({start['x']!r}, {start['y']!r})")
    to = browser.evaluate(f"{s}.toScreen({start['x'] + 3!r}, {start['y'] + 1!r})")
    mouse(browser, "mousePressed", at["x"], at["y"], button="left", buttons=1, clickCount=1)
    if browser.evaluate(f"{s}.grabbed()") != top:
        raise AssertionError(f"sandbox: pressing on body {top} did not grab it")
    for i in range(1, 11):
        mouse(browser, "mouseMoved", at["x"] + (to["x"] - at["x"]) * i / 10, at["y"] + (to["y"] - at["y"]) * i / 10,
              button="left", buttons=1)
    browser.evaluate(f"{s}.step(90)")
    pulled = browser.evaluate(f"{s}.state({top})")
    mouse(browser, "mouseReleased", to["x"], to["y"], button="left", buttons=0, clickCount=1)
    if browser.evaluate(f"{s}.grabbed()") != -1:
        raise AssertionError("sandbox: releasing the button did not release the body")
    if not pulled["x"] > start["x"] + 2.0:
        raise AssertionError(f"sandbox: the pulled box moved from x = {start['x']:.3f} to {pulled['x']:.3f}, "
                             f"not towards the cursor at {start['x'] + 3:.3f}")
    # Gravity upwards: a dropped circle rises.
    browser.evaluate(f"{s}.setGravity(0, 10)")
    ball = browser.evaluate(f"{s}.drop('circle', -14, 6)")
    browser.evaluate(f"{s}.step(30)")
    rise = browser.evaluate(f"{s}.state({ball})")
    if not (rise["vy"] > 4.9 and rise["y"] > 6):
        raise AssertionError(f"sandbox: with gravity (0, 10) a dropped circle has vy = {rise['vy']}, y = {rise['y']}")
    browser.evaluate(f"{s}.setGravity(0, -10)")
    browser.evaluate(f"{s}.step(60)")
    browser.evaluate(f"{s}.fit()")
    png, image = browser.screenshot()
    drawn = check_pixels(browser, image, hex_rgb(browser.evaluate(f"{s}.background")), "sandbox")
    if shot:
        Path(shot).write_bytes(png)
    return (f"played {played} steps in 1 s; a click dropped a box that falls; a drag pulled the top box "
            f"from x = {start['x']:.2f} to {pulled['x']:.2f} m; gravity (0, 10) lifts a circle; "
            f"{drawn} bodies seen in the screenshot")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--cli", required=True, help="the native tamias2d executable")
    ap.add_argument("--page", default=str(ROOT / "build-wasm" / "sandbox.html"))
    ap.add_argument("--shot", help="keep the screenshot as this PNG")
    ap.add_argument("--chromium", help="the browser (default: /usr/bin/chromium, then PATH)")
    ap.add_argument("cases", nargs="*", default=["pyramid20.json:120:20"],
                    help="scene.json:STEPS:EVERY, an example scene")
    args = ap.parse_args()
    cases = []
    for c in args.cases:
        try:
            name, steps, every = c.split(":")
            cases.append((name, int(steps), int(every)))
        except ValueError:
            ap.error(f"a case is scene.json:STEPS:EVERY, not {c!r}")
    page = Path(args.page)
    if not page.is_file():
        print(f"check_sandbox: {page} is missing (scripts/build_wasm.sh builds it): not checked")
        return SKIP
    chromium = find_chromium(args.chromium)
    if chromium is None:
        print("check_sandbox: Chromium is not installed (Debian package 'chromium'): not checked")
        return SKIP
    failures = 0
    with tempfile.TemporaryDirectory(prefix="tamias-sandbox-") as tmp:
        work = Path(tmp)
        (work / "profile").mkdir()
        cli = args.cli
        browser = Browser(chromium, str(work / "profile"))
        try:
            browser.open_page()
            browser.call("Page.navigate", {"url": page.resolve().as_uri()})
            deadline = time.monotonic() + 60
            while True:
                status = browser.evaluate("window.tamiasSandbox ? (tamiasSandbox.ready ? 'ready' : "
                                          "(tamiasSandbox.error || 'loading')) : 'loading'")
                if status == "ready":
                    break
                if status != "loading" or time.monotonic() > deadline:
                    raise AssertionError(f"sandbox: the page is not ready: {status}")
                time.sleep(0.05)
            for case in cases:
                try:
                    print("OK: " + compare(browser, cli, case, work))
                except AssertionError as e:
                    print(f"FAILED: {e}")
                    failures += 1
            print("OK: " + check_interaction(browser, args.shot))
            errors = page_errors(browser)
            if errors:
                raise AssertionError("sandbox: " + "; ".join(errors[:5]))
        except (AssertionError, CdpError) as e:
            print(f"FAILED: {e}")
            failures += 1
        finally:
            browser.close()
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
