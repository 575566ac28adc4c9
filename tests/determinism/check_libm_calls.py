#!/usr/bin/python3
"""Fails when the library calls a libm function that IEEE 754 does not require to be exactly
rounded (sin, cos, exp, pow, hypot, ...): such a function's last bit differs between C
libraries (glibc, musl, Apple's, Microsoft's), and so would a world's state. The library
computes those itself (src/tamias2d/math/); what it may take from libm is the ALLOWED set below,
whose results IEEE 754 defines exactly (square root, remainders, rounding to integers, sign and
exponent manipulation).

    check_libm_calls.py [--nm NM] [--allow NAME ...] LIBRARY...
    check_libm_calls.py --self-test --cxx COMPILER [--nm NM]

LIBRARY: a static library or object (`nm -u`) or a shared library (`nm -D -u`). A libm function
is any name the platform's libm.so.6 exports (nm -D) or <math.h> declares (the list below, with
its float and long double forms). The self-test compiles one object that calls std::sin and one
that calls only std::sqrt and std::fmod, and checks that the first fails and the second passes.
"""
import argparse
import glob
import os
import re
import subprocess
import sys
import tempfile

# C17 <math.h> and the GNU extensions glibc's libm exports, in double form; each also counts
# with the f and l suffixes.
MATH_H = """
acos asin atan atan2 cos sin tan acosh asinh atanh cosh sinh tanh exp exp2 expm1 frexp ilogb
ldexp log log10 log1p log2 logb modf scalbn scalbln cbrt fabs hypot pow sqrt erf erfc lgamma
tgamma ceil floor nearbyint rint lrint llrint round lround llround trunc fmod remainder remquo
copysign nan nextafter nexttoward fdim fmax fmin fma
sincos exp10 pow10 j0 j1 jn y0 y1 yn gamma lgamma_r drem significand scalb finite isinf isnan
""".split()

# Exactly rounded or exact: IEEE 754's operations (sqrt, the remainders, rounding to an
# integer) and bit manipulations (fabs, copysign, frexp, ldexp ...), whose results every
# conforming libm gives alike. fma is exact too, but is left out: the library forbids
# contraction, so a call to fma would be a change of method, to be allowed (--allow fma) only
# where it is pinned on every platform.
ALLOWED = """
sqrt fabs floor ceil trunc round lround llround rint lrint llrint nearbyint fmod remainder remquo
copysign fmin fmax fdim frexp ldexp scalbn scalbln ilogb logb modf nextafter nexttoward nan
finite isinf isnan
__fpclassify __signbit __isnan __isinf __finite __issignaling
feclearexcept fegetexceptflag feraiseexcept fesetexceptflag fetestexcept fegetround fesetround
fegetenv feholdexcept fesetenv feupdateenv
""".split()


def with_suffixes(names):
    return {n + s for n in names for s in ("", "f", "l")}


def platform_libm():
    """Paths of the platform's libm.so.6 (ldconfig's cache, then the usual directories)."""
    paths = []
    try:
        out = subprocess.run(["ldconfig", "-p"], capture_output=True, text=True, check=False).stdout
        paths = [line.split("=>")[-1].strip() for line in out.splitlines() if "libm.so.6 " in line]
    except FileNotFoundError:
        pass
    paths += glob.glob("/lib/*/libm.so.6") + glob.glob("/usr/lib/*/libm.so.6") + glob.glob("/lib64/libm.so.6")
    return sorted({p for p in paths if os.path.exists(p)})


def symbols(nm, path, args):
    out = subprocess.run([nm, *args, path], capture_output=True, text=True)
    if out.returncode != 0:
        sys.exit(f"check_libm_calls: {nm} {' '.join(args)} {path} failed: {out.stderr.strip()}")
    return out.stdout


def libm_names(nm):
    names = with_suffixes(MATH_H)
    for lib in platform_libm():
        for line in symbols(nm, lib, ["-D", "--defined-only"]).splitlines():
            fields = line.split()
            if len(fields) >= 3 and fields[1] in "TWiT":
                names.add(fields[2].split("@")[0])
    return names


def undefined(nm, path):
    """{symbol: [objects that call it]} of a static library, object or shared library."""
    shared = re.search(r"\.so(\.\d+)*$", path) is not None
    text = symbols(nm, path, ["-D", "-u"] if shared else ["-u", "-A"])
    found = {}
    for line in text.splitlines():
        fields = line.split()
        if not fields:
            continue
        name = fields[-1].split("@")[0]
        # nm -A: "library.a:member.o: U name" or "object.o: U name"
        where = os.path.basename(fields[0].rstrip(":").split(":")[-1]) if not shared else os.path.basename(path)
        found.setdefault(name, []).append(where)
    return found


def check(nm, libraries, allowed):
    names = libm_names(nm)
    allowed = with_suffixes(allowed)
    failures = 0
    for path in libraries:
        calls = {s: w for s, w in undefined(nm, path).items() if s in names}
        bad = {s: w for s, w in calls.items() if s not in allowed}
        ok = sorted(s for s in calls if s in allowed)
        print(f"{path}: libm calls {', '.join(sorted(calls)) or 'none'}"
              f" (allowed: {', '.join(ok) or 'none'})")
        for s, where in sorted(bad.items()):
            print(f"FAIL {path}: calls {s}, which is not exactly rounded (in {', '.join(sorted(set(where)))}):"
                  " its bits differ between C libraries; use the project's own (src/tamias2d/math/)")
            failures += 1
    return failures


def self_test(nm, cxx):
    cases = {
        "calls_sin": ("#include <cmath>\ndouble f(double x) { return std::sin(x); }\n", 1),
        "calls_exact": ("#include <cmath>\ndouble f(double x, double y) "
                        "{ return std::sqrt(x) + std::fmod(x, y); }\n", 0),
    }
    wrong = 0
    with tempfile.TemporaryDirectory() as tmp:
        for name, (source, expected) in cases.items():
            src = os.path.join(tmp, name + ".cpp")
            obj = os.path.join(tmp, name + ".o")
            with open(src, "w", encoding="utf-8") as f:
                f.write(source)
            # -fno-builtin: so that the compiler keeps the calls as written (it may otherwise
            # inline sqrt, and would fold a constant argument)
            subprocess.run([cxx, "-O2", "-fno-builtin", "-c", src, "-o", obj], check=True)
            got = check(nm, [obj], ALLOWED)
            verdict = "fails" if got else "passes"
            print(f"self-test {name}: {verdict} (expected: {'fails' if expected else 'passes'})")
            wrong += (got != 0) != (expected != 0)
    return wrong


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("libraries", nargs="*")
    parser.add_argument("--nm", default="nm")
    parser.add_argument("--allow", nargs="*", default=[], help="more allowed names (e.g. fma)")
    parser.add_argument("--self-test", action="store_true")
    parser.add_argument("--cxx", default="c++")
    args = parser.parse_args()
    if args.self_test:
        sys.exit(1 if self_test(args.nm, args.cxx) else 0)
    if not args.libraries:
        parser.error("no library given")
    failures = check(args.nm, args.libraries, ALLOWED + args.allow)
    if failures:
        print(f"check_libm_calls: {failures} call(s) of libm functions outside the allowed set")
    else:
        print(f"check_libm_calls: the {len(args.libraries)} libraries call no libm function outside the allowed set")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
