#!/usr/bin/python3
"""Every public header (include/tamias2d/) compiles on its own and includes nothing but other
public headers and the C++ standard library: no Boost, no JSON library, no private header. Each
compiles with -fno-exceptions too (a game without exceptions includes them: no inline code of
theirs throws when exceptions are off).

    check_public_headers.py <source_dir> <build_dir> <c++ compiler>

Oracle: the compiler's own list of the files each header opens (-H)."""
import pathlib
import subprocess
import sys

source, build, cxx = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2]), sys.argv[3]
public_roots = [(source / "include").resolve(), (build / "include").resolve()]
# The standard library's headers: what an empty program that includes <vector> opens lives here.
std_roots = set()
probe = subprocess.run([cxx, "-std=c++20", "-H", "-fsyntax-only", "-x", "c++", "-"],
                       input="#include <vector>\n#include <string>\n", text=True,
                       capture_output=True)
for line in probe.stderr.splitlines():
    if line.startswith("."):
        path = pathlib.Path(line.lstrip(". ").strip()).resolve()
        std_roots.add(path.parent if "bits" not in path.parts else path.parent.parent)

def allowed(path):
    if any(path.is_relative_to(r) for r in public_roots):
        return True
    text = str(path)
    if any(bad in text for bad in ("/boost/", "/nlohmann/", "/eigen3/", "/gsl/")):
        return False
    return any(path.is_relative_to(r) for r in std_roots) or text.startswith("/usr/include/")

headers = sorted((source / "include" / "tamias2d").rglob("*.hpp"))
passed = failed = 0
for h, flags in [(h, f) for h in headers for f in ([], ["-fno-exceptions"])]:
    name = h.relative_to(source / "include")
    run = subprocess.run([cxx, "-std=c++20", "-Wall", "-Wextra", "-Wpedantic", "-Werror", "-H",
                          "-fsyntax-only", *flags, "-I", str(source / "include"),
                          "-I", str(build / "include"), "-x", "c++", "-"],
                         input=f'#include "{name}"\n', text=True, capture_output=True)
    if flags:
        name = f"{name} {' '.join(flags)}"
    opened = [pathlib.Path(l.lstrip(". ").strip()).resolve()
              for l in run.stderr.splitlines() if l.startswith(". ") or l.startswith("..")]
    bad = [str(p) for p in opened if not allowed(p)]
    errors = [l for l in run.stderr.splitlines() if not l.startswith(".")]
    if run.returncode != 0 or bad:
        failed += 1
        print(f"FAIL {name}: " + ("; ".join(errors[:3]) if run.returncode else "includes " +
                                   ", ".join(bad[:3])))
    else:
        passed += 1
        print(f"ok   {name} ({len(opened)} files opened)")
print(f"{passed} passed, {failed} failed")
sys.exit(1 if failed or not headers else 0)
