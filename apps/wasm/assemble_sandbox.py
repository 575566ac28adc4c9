#!/usr/bin/env python3
"""Assembles the live sandbox's page (scripts/build_wasm.sh): the template apps/wasm/sandbox.html
with the player's styles, the emscripten module (the .wasm inside it), the player's drawing code,
the sandbox's script and the example scenes inlined, so that the page opens from disk alone."""
import argparse
import json
from pathlib import Path


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    for name in ("template", "css", "player-js", "sandbox-js", "module", "scenes", "output"):
        ap.add_argument(f"--{name}", *(["-o"] if name == "output" else []), required=True)
    a = ap.parse_args()
    scenes = {p.name: p.read_text(encoding="utf-8") for p in sorted(Path(a.scenes).glob("*.json"))}
    # JSON in a <script> element: "</" written "<\/" (the same string in JSON) cannot end it.
    scenes_text = json.dumps(scenes, ensure_ascii=False).replace("</", "<\\/")
    js = "\n".join(Path(p).read_text(encoding="utf-8") for p in (a.module, a.player_js, a.sandbox_js))
    if "</script" in js.lower():
        raise SystemExit("assemble_sandbox: a script contains '</script'")
    page = Path(a.template).read_text(encoding="utf-8")
    for marker, text in (("CSS", Path(a.css).read_text(encoding="utf-8")), ("SCENES", scenes_text),
                         ("JS", js)):
        tag = f"<!--TAMIAS:{marker}-->"
        if page.count(tag) != 1:
            raise SystemExit(f"assemble_sandbox: the template needs one {tag}")
        page = page.replace(tag, text)
    Path(a.output).write_text(page, encoding="utf-8")


if __name__ == "__main__":
    main()
