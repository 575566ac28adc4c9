#!/usr/bin/env python3
"""Writes players with `tamias2d view` and checks them in headless Chromium.

    check_player.py --cli build/apps/cli/tamias2d [--out DIR] [--index FILE] CASE...

A CASE is a scene file, optionally followed by ':' and `view` options separated by spaces or
commas ("examples/scenes/rain.json:--steps 600 --every 4"). For each case the script writes
DIR/NAME.html with `tamias2d view` and the same frames as CSV with `tamias2d run`, then loads
the page in Chromium (the DevTools protocol over a pipe: no server, no Node, no extra package)
and checks that:

  * the page decodes its run (window.tamiasPlayer.ready) without a script error and requests
    nothing but the file itself (no network);
  * it plays: after a moment of play the frame has advanced;
  * the mouse works: pointing at a body shows its state, the wheel zooms about the cursor, a
    drag pans;
  * the recorded states the page returns (tamiasPlayer.state(frame, body)) equal the CLI's CSV
    rows of the same steps to within half a quantisation step;
  * a screenshot shows the scene: at the projected centre of sampled bodies, the pixels differ
    from the canvas background (at frame 0 and at the middle frame, whose screenshot is kept
    as DIR/NAME.png);
  * the page marks itself decoded (data-tamias-player="ready" on <html>), and, on the first
    page, docs/viewer.md's screenshot recipe (chromium --screenshot with a virtual-time budget)
    waits for the decoding: the DOM it dumps says "ready" and its canvas is drawn.

Exit status: 0 when every check passes, 1 when one fails, 77 when Chromium is not installed
(CTest's SKIP_RETURN_CODE; the pages are still written), 2 for a bad command line.
"""
from __future__ import annotations

import argparse
import base64
import csv
import io
import json
import math
import os
import re
import select
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

SKIP = 77
WIDTH, HEIGHT = 1200, 800
SAMPLED_FRAMES = 8   # frames whose states are compared (first, last and evenly between)
SAMPLED_BODIES = 400  # bodies compared per frame at most (evenly spread over the indexes)
DRAWN_BODIES = 12     # bodies whose pixels are checked per screenshot at most


def find_chromium(explicit):
    for c in ([explicit] if explicit else []) + ["/usr/bin/chromium", "chromium", "chromium-browser"]:
        path = shutil.which(c) if c else None
        if path:
            return path
    return None


def page_errors(browser):
    """What the page did wrong, from the events seen so far: script errors, console errors and
    any request that leaves the page (it must load nothing)."""
    errors = []
    for e in browser.events:
        m, p = e.get("method"), e.get("params", {})
        if m == "Runtime.exceptionThrown":
            d = p.get("exceptionDetails", {})
            errors.append("script error: " + (d.get("exception", {}).get("description") or d.get("text", "")))
        elif m == "Runtime.consoleAPICalled" and p.get("type") == "error":
            errors.append("console error: " + " ".join(str(a.get("value")) for a in p.get("args", [])))
        elif m == "Network.requestWillBeSent":
            url = p.get("request", {}).get("url", "")
            if not url.startswith(("file:", "data:", "blob:", "about:")):
                errors.append(f"network request: {url}")
    return errors


class CdpError(RuntimeError):
    pass


class Browser:
    """Headless Chromium driven through --remote-debugging-pipe: JSON messages separated by
    NUL bytes, commands on the child's fd 3, replies and events on its fd 4."""

    def __init__(self, exe, profile):
        to_child_r, self.to_child = os.pipe()
        self.from_child, from_child_w = os.pipe()

        def wire():  # in the child: the protocol's descriptors 3 and 4
            os.dup2(to_child_r, 100)
            os.dup2(from_child_w, 101)
            os.dup2(100, 3)
            os.dup2(101, 4)

        self.log = open(os.path.join(profile, "chromium.log"), "wb")
        self.proc = subprocess.Popen(
            [exe, "--headless", "--no-sandbox", "--disable-gpu", "--remote-debugging-pipe",
             "--no-first-run", "--disable-background-networking", "--disable-component-update",
             "--disable-sync", "--disable-dev-shm-usage", "--hide-scrollbars", "--mute-audio",
             f"--user-data-dir={profile}", f"--window-size={WIDTH},{HEIGHT}", "about:blank"],
            stdin=subprocess.DEVNULL, stdout=self.log, stderr=self.log,
            preexec_fn=wire, close_fds=False)
        os.close(to_child_r)
        os.close(from_child_w)
        self.buffer = b""
        self.next_id = 0
        self.events = []
        self.session = None

    def close(self):
        try:
            self.call("Browser.close", timeout=5, session=False)
        except Exception:  # noqa: BLE001 - closing anyway
            pass
        try:
            self.proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            self.proc.wait()
        for fd in (self.to_child, self.from_child):
            try:
                os.close(fd)
            except OSError:
                pass
        self.log.close()

    def _read_message(self, deadline):
        while b"\0" not in self.buffer:
            left = deadline - time.monotonic()
            if left <= 0:
                raise CdpError("timed out waiting for Chromium")
            ready, _, _ = select.select([self.from_child], [], [], left)
            if ready:
                chunk = os.read(self.from_child, 1 << 20)
                if not chunk:
                    raise CdpError("Chromium closed the protocol pipe")
                self.buffer += chunk
        message, self.buffer = self.buffer.split(b"\0", 1)
        return json.loads(message)

    def call(self, method, params=None, timeout=30, session=True):
        self.next_id += 1
        message = {"id": self.next_id, "method": method, "params": params or {}}
        if session and self.session:
            message["sessionId"] = self.session
        data = json.dumps(message).encode() + b"\0"
        while data:
            data = data[os.write(self.to_child, data):]
        deadline = time.monotonic() + timeout
        while True:
            reply = self._read_message(deadline)
            if reply.get("id") == self.next_id:
                if "error" in reply:
                    raise CdpError(f"{method}: {reply['error'].get('message')}")
                return reply.get("result", {})
            if "method" in reply:
                self.events.append(reply)

    def open_page(self):
        target = self.call("Target.createTarget", {"url": "about:blank"}, session=False)["targetId"]
        self.session = self.call("Target.attachToTarget", {"targetId": target, "flatten": True},
                                 session=False)["sessionId"]
        for domain in ("Page", "Runtime", "Network", "Log"):
            self.call(f"{domain}.enable")
        self.call("Emulation.setDeviceMetricsOverride",
                  {"width": WIDTH, "height": HEIGHT, "deviceScaleFactor": 1, "mobile": False})

    def evaluate(self, expression, timeout=30):
        result = self.call("Runtime.evaluate", {"expression": expression, "returnByValue": True,
                                                "awaitPromise": True}, timeout=timeout)
        if "exceptionDetails" in result:
            d = result["exceptionDetails"]
            raise CdpError(f"{expression[:60]}...: {d.get('exception', {}).get('description') or d.get('text')}")
        return result["result"].get("value")

    def screenshot(self):
        from PIL import Image  # python3-pil (a dependency of python3-matplotlib, scripts/setup.sh)
        data = base64.b64decode(self.call("Page.captureScreenshot", {"format": "png"})["data"])
        return data, Image.open(io.BytesIO(data)).convert("RGB")


def split_case(case):
    """'scene.json:--every 4 --steps 600' -> (Path, ['--every', '4', '--steps', '600'])."""
    at = case.find(".json:")
    if at < 0:
        return Path(case), []
    return Path(case[:at + 5]), case[at + 6:].replace(",", " ").replace("=", " ").split()


def read_csv(path):
    frames = {}
    with open(path, newline="") as fh:
        for row in csv.DictReader(fh):
            frames.setdefault(int(row["step"]), []).append(row)
    return frames


def page_summary(page):
    """Frames, bodies, joints and description of the run embedded in a page."""
    text = page.read_text(encoding="utf-8")
    begin = text.index('id="tamias-run">') + len('id="tamias-run">')
    data = json.loads(text[begin:text.index("</script>", begin)])
    return {"frames": len(data["frames"]["step"]), "bodies": len(data["bodies"]),
            "joints": len(data["joints"]), "description": data["description"]}


# docs/viewer.md's screenshot recipe ("A screenshot of a page"): Chromium's own --screenshot,
# with a virtual-time budget so that it runs the page's decoding before it captures.
RECIPE_FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                "--disable-background-networking", "--disable-component-update", "--disable-sync",
                "--hide-scrollbars", f"--window-size={WIDTH},{HEIGHT}", "--virtual-time-budget=5000"]


def check_recipe(chromium, page, work, frame, background, label):
    """The recipe on `page` at `frame`: the DOM Chromium dumps with the same flags says the run
    is decoded, and the screenshot's canvas is drawn: over 1 % of its pixels differ from the
    background (a page still decoding shows the background and one line of text, 0.1 %)."""
    from PIL import Image
    url = page.resolve().as_uri() + f"#frame={frame}"
    shot = work / "recipe.png"
    outputs = {}
    for mode in ("--dump-dom", f"--screenshot={shot}"):
        profile = Path(tempfile.mkdtemp(prefix="profile-", dir=work))
        try:
            run = subprocess.run([chromium, *RECIPE_FLAGS, f"--user-data-dir={profile}", mode, url],
                                 capture_output=True, text=True, timeout=120)
        finally:
            shutil.rmtree(profile, ignore_errors=True)
        if run.returncode != 0:
            raise AssertionError(f"{label}: recipe: chromium {mode} failed: {run.stderr.strip()[-300:]}")
        outputs[mode] = run.stdout
    status = re.search(r'<html[^>]*data-tamias-player="([a-z]*)"', outputs["--dump-dom"])
    if not status or status.group(1) != "ready":
        raise AssertionError(f"{label}: recipe: the page is "
                             f"{status.group(1) if status else 'without its status'} when captured")
    image = Image.open(shot).convert("RGB")
    if image.size != (WIDTH, HEIGHT):
        raise AssertionError(f"{label}: recipe: a {image.size} screenshot, expected {(WIDTH, HEIGHT)}")
    stage = [image.getpixel((x, y)) for x in range(0, int(0.7 * WIDTH), 3)
             for y in range(int(0.1 * HEIGHT), HEIGHT, 3)]
    drawn = sum(1 for p in stage if p != background) / len(stage)
    if drawn <= 0.01:
        raise AssertionError(f"{label}: recipe: {100 * drawn:.2f} % of the canvas drawn: not decoded?")
    return f"the screenshot recipe captures it decoded ({100 * drawn:.0f} % of the canvas drawn)"


def hex_rgb(colour):
    return tuple(int(colour[i:i + 2], 16) for i in (1, 3, 5))


def check_pixels(browser, image, frame, background, label):
    """Pixels at the projected centres of sampled non-static bodies differ from the background."""
    sample = browser.evaluate(f"""(() => {{
        const p = window.tamiasPlayer, out = [];
        for (let b = 0; b < p.bodyCount; b++) {{
          const s = p.state({frame}, b), c = p.toScreen(s.x, s.y), e = p.toScreen(s.x + p.radius(b), s.y);
          out.push([b, p.type(b), c.x, c.y, Math.abs(e.x - c.x)]);
        }}
        return out; }})()""")
    candidates = [s for s in sample if s[1] != "static" and s[4] >= 3
                  and 2 <= s[2] < WIDTH - 2 and 2 <= s[3] < HEIGHT - 2]
    if not candidates:  # only static or tiny bodies on screen: check any body drawn
        candidates = [s for s in sample if 2 <= s[2] < WIDTH - 2 and 2 <= s[3] < HEIGHT - 2]
    if not candidates:
        raise AssertionError(f"{label}: no body is on the screen")
    step = max(1, len(candidates) // DRAWN_BODIES)
    chosen = candidates[::step][:DRAWN_BODIES]
    missing = []
    for b, _, x, y, _ in chosen:
        near = [image.getpixel((int(x) + dx, int(y) + dy)) for dx in (-1, 0, 1) for dy in (-1, 0, 1)]
        if not any(sum(abs(p[i] - background[i]) for i in range(3)) > 30 for p in near):
            missing.append(f"body {b} at ({x:.0f}, {y:.0f})")
    if missing:
        raise AssertionError(f"{label}: background colour where bodies should be: {', '.join(missing)}")
    return len(chosen)


def check_interaction(browser, label):
    """The mouse as a user moves it: pointing at a body shows its state, the wheel zooms about
    the cursor, a drag pans."""
    def mouse(kind, x, y, **extra):
        browser.call("Input.dispatchMouseEvent", {"type": kind, "x": x, "y": y, **extra})
        browser.evaluate("new Promise(r => requestAnimationFrame(() => requestAnimationFrame(r)))")

    target = browser.evaluate("""(() => {
        const p = tamiasPlayer, f = p.frame();
        for (let b = 0; b < p.bodyCount; b++) {
          if (p.type(b) === 'static') continue;
          const s = p.state(f, b), c = p.toScreen(s.x, s.y), e = p.toScreen(s.x + p.radius(b), s.y);
          if (Math.abs(e.x - c.x) >= 4 && c.x > 10 && c.y > 50 && c.x < 880 && c.y < 780) return [b, c.x, c.y, s.x, s.y];
        }
        return null; })()""")
    if target is None:
        return "no body large enough to point at"
    b, x, y, wx, wy = target
    mouse("mouseMoved", x, y)
    hovered = browser.evaluate("tamiasPlayer.hovered()")
    info = browser.evaluate("document.getElementById('body-info').textContent")
    if hovered < 0 or "m/s" not in info:
        raise AssertionError(f"{label}: pointing at body {b} shows no body state ({info[:80]!r})")
    before = browser.evaluate("tamiasPlayer.view()")
    mouse("mouseWheel", x, y, deltaX=0, deltaY=-300)
    after = browser.evaluate("tamiasPlayer.view()")
    moved = browser.evaluate(f"tamiasPlayer.toScreen({wx!r}, {wy!r})")
    if not after["scale"] > before["scale"] * 1.2 or abs(moved["x"] - x) > 1 or abs(moved["y"] - y) > 1:
        raise AssertionError(f"{label}: the wheel did not zoom about the cursor ({before} -> {after})")
    mouse("mousePressed", x, y, button="left", buttons=1, clickCount=1)
    mouse("mouseMoved", x + 40, y + 30, button="left", buttons=1)
    mouse("mouseReleased", x + 40, y + 30, button="left", buttons=0, clickCount=1)
    moved = browser.evaluate(f"tamiasPlayer.toScreen({wx!r}, {wy!r})")
    if abs(moved["x"] - (x + 40)) > 1 or abs(moved["y"] - (y + 30)) > 1:
        raise AssertionError(f"{label}: a drag did not pan the view with the cursor")
    mouse("mouseMoved", WIDTH - 20, HEIGHT - 20)  # off the canvas: no highlight in screenshots
    browser.evaluate("tamiasPlayer.fit()")
    return f"hover, zoom and pan on body {b} ({browser.evaluate(f'tamiasPlayer.name({b})')})"


def compare_states(browser, frames_csv, quantum, label):
    steps = sorted(frames_csv)
    count, bodies = browser.evaluate("[tamiasPlayer.frameCount, tamiasPlayer.bodyCount]")
    if count != len(steps):
        raise AssertionError(f"{label}: the page has {count} frames, the CSV {len(steps)}")
    if bodies != len(frames_csv[steps[0]]):
        raise AssertionError(f"{label}: the page has {bodies} bodies, the CSV {len(frames_csv[steps[0]])}")
    picks = sorted({round(i * (count - 1) / (SAMPLED_FRAMES - 1)) for i in range(SAMPLED_FRAMES)})
    body_step = max(1, math.ceil(bodies / SAMPLED_BODIES))
    body_picks = list(range(0, bodies, body_step))
    states = browser.evaluate(
        f"{json.dumps(picks)}.map(f => {json.dumps(body_picks)}.map(b => tamiasPlayer.state(f, b)))")
    tol = {"x": quantum["position"], "y": quantum["position"], "vx": quantum["velocity"],
           "vy": quantum["velocity"], "omega": quantum["angular_velocity"]}
    worst = {}
    compared = 0
    for f, row in zip(picks, states):
        rows = frames_csv[steps[f]]
        for b, s in zip(body_picks, row):
            c = rows[b]
            where = f"{label}: frame {f} (step {steps[f]}), body {b} '{c['name']}'"
            if s["step"] != steps[f] or s["time"] != float(c["time"]):
                raise AssertionError(f"{where}: step/time {s['step']}/{s['time']!r}, CSV {steps[f]}/{c['time']}")
            for key, q in tol.items():
                v = float(c[key])
                err = abs(s[key] - v)
                if err > 0.5 * q * (1 + 1e-6) + 1e-12 * abs(v):
                    raise AssertionError(f"{where}: {key} = {s[key]!r}, CSV {v!r}: off by {err:.3g}, "
                                         f"more than half the quantum {q}")
                worst[key] = max(worst.get(key, 0.0), err / q)
            phi = float(c["phi"])
            err = abs(math.remainder(s["phi"] - phi, 2 * math.pi))
            if err > 0.5 * quantum["angle"] * (1 + 1e-6) + 1e-12:
                raise AssertionError(f"{where}: phi = {s['phi']!r}, CSV {phi!r}: off by {err:.3g}")
            worst["phi"] = max(worst.get("phi", 0.0), err / quantum["angle"])
            compared += 1
    return compared, max(worst.values(), default=0.0)


def check_page(browser, page, csv_path, shot_path, label):
    browser.events.clear()
    browser.call("Page.navigate", {"url": page.resolve().as_uri()})
    deadline = time.monotonic() + 60
    while True:
        status = browser.evaluate("window.tamiasPlayer ? (window.tamiasPlayer.ready ? 'ready' : "
                                  "(window.tamiasPlayer.error || 'loading')) : 'loading'")
        if status == "ready":
            break
        if status != "loading":
            raise AssertionError(f"{label}: the page reports: {status}")
        if time.monotonic() > deadline:
            raise AssertionError(f"{label}: the player was not ready after 60 s")
        time.sleep(0.05)
    marker = browser.evaluate("document.documentElement.dataset.tamiasPlayer")
    if marker != "ready":
        raise AssertionError(f"{label}: ready, but <html data-tamias-player> is {marker!r}")
    frames_csv = read_csv(csv_path)
    quantum = browser.evaluate("tamiasPlayer.quantum")
    background = hex_rgb(browser.evaluate("tamiasPlayer.background"))
    compared, worst = compare_states(browser, frames_csv, quantum, label)

    count = browser.evaluate("tamiasPlayer.frameCount")
    browser.evaluate("tamiasPlayer.setFrame(0)")
    _, image = browser.screenshot()
    drawn = check_pixels(browser, image, 0, background, f"{label}: frame 0")

    played = 0
    if count > 1:  # play at 1x until the frame advances (frames may be a second apart)
        interval = browser.evaluate("tamiasPlayer.state(1, 0).time - tamiasPlayer.state(0, 0).time")
        browser.evaluate("tamiasPlayer.play()")
        deadline = time.monotonic() + max(1.0, interval) + 3.0
        while played == 0 and time.monotonic() < deadline:
            time.sleep(0.05)
            played = browser.evaluate("tamiasPlayer.frame()")
        browser.evaluate("tamiasPlayer.pause()")
        if played == 0:
            raise AssertionError(f"{label}: still at frame 0 after playing for {interval + 3:.1f} s")
    interaction = check_interaction(browser, label)
    middle = count // 2
    browser.evaluate(f"(tamiasPlayer.show('contacts', true), tamiasPlayer.show('trails', true), "
                     f"tamiasPlayer.setFrame({middle}))")
    png, image = browser.screenshot()
    drawn += check_pixels(browser, image, middle, background, f"{label}: frame {middle}")
    if shot_path:
        shot_path.write_bytes(png)

    errors = page_errors(browser)
    if errors:
        raise AssertionError(f"{label}: " + "; ".join(errors[:5]))
    return (count, background,
            f"{count} frames, {compared} states within half a quantum (worst {worst:.2f} of it), "
            f"{drawn} bodies seen in 2 screenshots, played to frame {played}, {interaction}")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--cli", required=True, help="the tamias2d executable")
    ap.add_argument("--out", help="directory for NAME.html and NAME.png (default: a temporary one)")
    ap.add_argument("--index", help="write a JSON list of the pages (for the report)")
    ap.add_argument("--chromium", help="the browser (default: /usr/bin/chromium, then PATH)")
    ap.add_argument("cases", nargs="+", help="scene.json[:view options]")
    args = ap.parse_args()

    work = Path(tempfile.mkdtemp(prefix="tamias-viewer-"))
    out = Path(args.out) if args.out else work
    out.mkdir(parents=True, exist_ok=True)
    chromium = find_chromium(args.chromium)
    browser = None
    failures, entries = 0, []
    recipe_checked = False
    try:
        for case in args.cases:
            scene, options = split_case(case)
            name = scene.stem
            if "--every" not in options:  # view's default, given to run too
                try:
                    every = json.loads(scene.read_text()).get("output_every", 0) or 1
                except (OSError, ValueError, AttributeError):
                    every = 1  # the CLI reports what is wrong with the scene
                options += ["--every", str(every)]
            page, csv_path = out / f"{name}.html", work / f"{name}.csv"
            run_options = [o for i, o in enumerate(options)
                           if o != "--max-contacts" and (i == 0 or options[i - 1] != "--max-contacts")]
            # The page and the CSV are two runs of the same scene: side by side.
            t0 = time.monotonic()
            run = subprocess.Popen([args.cli, "run", str(scene), *run_options, "-o", str(csv_path)],
                                   stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
            view = subprocess.run([args.cli, "view", str(scene), *options, "-o", str(page)],
                                  capture_output=True, text=True)
            seconds = time.monotonic() - t0
            run_errors = run.communicate()[1]
            entry = {"name": name, "scene": str(scene), "options": " ".join(options),
                     "page": page.name, "seconds": round(seconds, 2)}
            entries.append(entry)
            if view.returncode != 0 or run.returncode != 0:
                entry["result"] = "failed: " + (view.stderr or run_errors).strip()
                print(f"{name}: FAILED: {(view.stderr or run_errors).strip()}")
                failures += 1
                continue
            entry["bytes"] = page.stat().st_size
            entry.update(page_summary(page))
            size = f"{entry['bytes'] / 1e6:.2f} MB" if entry["bytes"] >= 1e5 else f"{entry['bytes'] / 1e3:.0f} kB"
            if chromium is None:
                entry["result"] = "not checked: Chromium is not installed"
                print(f"{name}: written ({size}, {seconds:.1f} s); not checked: Chromium is not installed")
                continue
            shot = out / f"{name}.png" if args.out else None
            try:
                if browser is None:
                    profile = work / "profile"
                    profile.mkdir(exist_ok=True)
                    browser = Browser(chromium, str(profile))
                    browser.open_page()
                count, background, summary = check_page(browser, page, csv_path, shot, name)
                if not recipe_checked:
                    summary += "; " + check_recipe(chromium, page, work, count // 2, background, name)
                    recipe_checked = True
                entry["result"] = "OK: " + summary
                if shot:
                    entry["screenshot"] = shot.name
                print(f"{name}: OK: {size}, written in {seconds:.1f} s; {summary}")
            except (AssertionError, CdpError) as e:
                entry["result"] = f"failed: {e}"
                print(f"{name}: FAILED: {e}")
                failures += 1
    finally:
        if browser:
            browser.close()
        shutil.rmtree(work, ignore_errors=True)
    if args.index:
        Path(args.index).write_text(json.dumps(entries, indent=1) + "\n")
    if failures:
        return 1
    if chromium is None:
        print("check_player: Chromium is not installed (Debian package 'chromium'): pages not checked")
        return SKIP
    return 0


if __name__ == "__main__":
    sys.exit(main())
